using System.Globalization;
using System.Net;

namespace RobotControl.WebConsole.Server;

/// <summary>A <c>host:port</c> the console listens on (<c>127.0.0.1:5080</c>, <c>0.0.0.0:5080</c>, <c>[::1]:5080</c>, <c>localhost:5080</c>).</summary>
/// <param name="Address">The address.</param>
/// <param name="Port">The port (0: any free port).</param>
public sealed record BindAddress(IPAddress Address, int Port)
{
    /// <summary>True when only this machine can connect.</summary>
    public bool IsLoopback => IPAddress.IsLoopback(Address);

    /// <summary>Parses <paramref name="text"/>.</summary>
    /// <exception cref="FormatException">Not <c>host:port</c> with an IP address or <c>localhost</c> and a port 0..65535.</exception>
    public static BindAddress Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var colon = text.LastIndexOf(':');
        if (colon <= 0 || !int.TryParse(text[(colon + 1)..], NumberStyles.None, CultureInfo.InvariantCulture, out var port) || port > 65535)
        {
            throw new FormatException($"--bind '{text}': give host:port, e.g. 127.0.0.1:5080");
        }

        var host = text[..colon].Trim('[', ']');
        var address = host.Equals("localhost", StringComparison.OrdinalIgnoreCase) ? IPAddress.Loopback
            : IPAddress.TryParse(host, out var ip) ? ip
            : throw new FormatException($"--bind '{text}': '{host}' is not an IP address (use 127.0.0.1, 0.0.0.0, an interface's address or localhost)");
        return new BindAddress(address, port);
    }

    /// <inheritdoc />
    public override string ToString() => Address.AddressFamily == System.Net.Sockets.AddressFamily.InterNetworkV6 ? $"[{Address}]:{Port}" : $"{Address}:{Port}";
}
