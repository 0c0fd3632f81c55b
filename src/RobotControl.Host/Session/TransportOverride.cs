using RobotControl.Bus.Transports;

namespace RobotControl.Host.Session;

/// <summary>
/// A transport given on the command line (<c>--transport</c>) in place of the graph's, checked before anything is
/// loaded or opened: the string parses, and a serial device or USB adapter it names exists.
/// </summary>
public static class TransportOverride
{
    /// <summary>Parses and checks <paramref name="transport"/>; returns it parsed.</summary>
    /// <exception cref="FormatException">
    /// One line naming the option and the problem: the string is malformed (unknown scheme, bad option), or the
    /// device it names does not exist.
    /// </exception>
    public static LinkUri Check(string transport)
    {
        ArgumentNullException.ThrowIfNull(transport);
        LinkUri uri;
        try
        {
            uri = LinkUri.Parse(transport);
        }
        catch (Exception ex) when (ex is FormatException or ArgumentException)
        {
            throw new FormatException($"--transport: {ex.Message}", ex);
        }

        switch (uri.Kind)
        {
            case LinkKind.Serial when !File.Exists(uri.Target):
                throw new FormatException($"--transport {transport}: no device {uri.Target}");
            case LinkKind.Usb:
                try
                {
                    var (vendor, product, serial) = uri.UsbIds();
                    _ = UsbSerialResolver.Resolve(vendor, product, serial);
                }
                catch (IOException ex)
                {
                    throw new FormatException($"--transport {transport}: {ex.Message}", ex);
                }

                break;
        }

        return uri;
    }
}
