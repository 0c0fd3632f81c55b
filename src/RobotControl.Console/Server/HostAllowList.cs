using System.Net;
using System.Net.NetworkInformation;
using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The host names the console answers to (the <c>Host</c> header, port aside): the loopback names, the bind address,
/// on a wildcard bind this machine's name and interface addresses, and the names given with <c>--allowed-host</c>.
/// Anything else is refused before any other check: a page of another site whose name was re-pointed at this machine
/// (DNS rebinding) sends its own name as the Host, so it never reaches the API.
/// </summary>
internal sealed class HostAllowList
{
    private readonly HashSet<string> _names = new(StringComparer.OrdinalIgnoreCase) { "localhost", "127.0.0.1", "::1" };

    /// <summary>The names for <paramref name="bind"/> plus <paramref name="extra"/>; <paramref name="printed"/> is the host of the URL the console prints.</summary>
    public HostAllowList(BindAddress bind, IEnumerable<string> extra, string printed)
    {
        _names.Add(Normal(printed));
        if (bind.Address.Equals(IPAddress.Any) || bind.Address.Equals(IPAddress.IPv6Any))
        {
            foreach (var address in NetworkInterface.GetAllNetworkInterfaces().SelectMany(i => i.GetIPProperties().UnicastAddresses))
            {
                _names.Add(address.Address.ToString());
            }
        }
        else
        {
            _names.Add(bind.Address.ToString());
        }

        foreach (var name in extra)
        {
            _names.Add(Normal(name));
        }
    }

    /// <summary>True when <paramref name="host"/> names this console.</summary>
    public bool Allows(HostString host) => host.HasValue && _names.Contains(Normal(host.Host));

    private static string Normal(string name) => name.Trim().TrimStart('[').TrimEnd(']').TrimEnd('.');
}
