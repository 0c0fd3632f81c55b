using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Host.Session;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// The bus a command was given, re-openable at another baud: what a baud change and a baud scan need, since the host's
/// end of a serial line runs at one baud at a time. Every other transport option (parity, RS-485 driver-enable, ...)
/// is kept as given.
/// </summary>
internal sealed class BusLine
{
    /// <param name="transport">The transport as given (any <c>?baud=</c> is the starting baud).</param>
    /// <param name="robotFile">The robot file, if any.</param>
    /// <param name="options">Timing of the client on every opening.</param>
    public BusLine(string transport, string? robotFile, BusClientOptions options)
    {
        Uri = RobotConnection.CheckTransport(transport);
        RobotFile = robotFile;
        Options = options;
    }

    /// <summary>The transport as parsed.</summary>
    public LinkUri Uri { get; }

    /// <summary>The robot file, if any.</summary>
    public string? RobotFile { get; }

    /// <summary>Timing of the client on every opening.</summary>
    public BusClientOptions Options { get; }

    /// <summary>The transport string for the same line at <paramref name="baud"/>.</summary>
    public string Transport(int baud)
    {
        var options = Uri.Options.Where(kv => kv.Key != "baud").Select(kv => $"{kv.Key}={kv.Value}").Append($"baud={baud}");
        return $"{Uri.Kind.ToString().ToLowerInvariant()}:{Uri.Target}?{string.Join('&', options)}";
    }

    /// <summary>Refuses (one line naming what to do instead) a transport whose host side cannot be re-opened at another baud.</summary>
    /// <exception cref="ArgumentException">The transport is <c>virtual:</c> or <c>tcp:</c>.</exception>
    public void RequireBaudSwitchable(string what)
    {
        if (Uri.Kind == LinkKind.Virtual)
        {
            throw new ArgumentException($"{what}: a virtual: robot is built anew at its transport's baud for every command; serve it with robotctl bus-sim --pty and use its serial: path; nothing was written");
        }

        if (Uri.Kind == LinkKind.Tcp)
        {
            throw new ArgumentException($"{what}: the serial speed of a TCP bridge is set on the bridge, not from here; use a serial: or usb: transport; nothing was written");
        }
    }

    /// <summary>
    /// Opens the line at <paramref name="baud"/> (with the robot file, if any); <paramref name="discoveryWindow"/>
    /// overrides the client's. Bytes left in the port's input from before (late replies at the previous baud) are dropped.
    /// </summary>
    public RobotConnection Open(int baud, TimeSpan? discoveryWindow = null)
    {
        var connection = RobotConnection.Open(Transport(baud), RobotFile, discoveryWindow is { } w ? Options with { DiscoveryWindow = w } : Options);
        connection.Client.Link.DiscardInput();
        return connection;
    }
}
