using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Bus.Transports;

/// <summary>
/// Opens the byte link a transport string names: serial, USB and TCP. A <c>virtual:</c> link belongs to a virtual
/// robot (RobotControl.Simulation's <c>VirtualRobot.OpenLink</c>), which also owns the simulated clock.
/// </summary>
public static class LinkFactory
{
    /// <summary>Opens the link a transport string names.</summary>
    /// <exception cref="FormatException">The string is malformed.</exception>
    /// <exception cref="IOException">The device cannot be found or opened.</exception>
    public static IByteLink Open(string transport) => Open(LinkUri.Parse(transport));

    /// <summary>Opens the link a parsed transport names.</summary>
    /// <exception cref="IOException">The device cannot be found or opened.</exception>
    public static IByteLink Open(LinkUri uri) => Open(uri, "/sys", "/dev");

    /// <summary>Opens the link a parsed transport names, looking for USB adapters under the given sysfs and /dev roots.</summary>
    internal static IByteLink Open(LinkUri uri, string sysRoot, string devRoot)
    {
        ArgumentNullException.ThrowIfNull(uri);
        switch (uri.Kind)
        {
            case LinkKind.Serial:
                _ = LatencyTimer.TrySetOneMs(uri.Target, sysRoot); // USB-serial adapters: 1 ms, not the default 16
                return SerialLink.Open(uri.Target, uri.BaudRate, uri.Parity, uri.Rs485);
            case LinkKind.Usb:
                // A USB-RS485 adapter is a serial device once found: same link, same options.
                var (vendor, product, serial) = uri.UsbIds();
                var device = UsbSerialResolver.Resolve(vendor, product, serial, sysRoot, devRoot);
                _ = LatencyTimer.TrySetOneMs(device, sysRoot);
                return SerialLink.Open(device, uri.BaudRate, uri.Parity, uri.Rs485);
            case LinkKind.Tcp:
                var (host, port) = uri.TcpEndpoint();
                return TcpLink.Connect(host, port, uri.BaudRate, TimeSpan.FromSeconds(3));
            default:
                throw new IOException($"{uri}: a virtual bus is opened from its virtual robot (VirtualRobot.OpenLink), which owns the simulated clock; robotctl does this for virtual: transports");
        }
    }
}
