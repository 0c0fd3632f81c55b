using System.Globalization;

namespace RobotControl.Bus.Transports;

/// <summary>
/// Finds the device node of a USB-serial adapter by vendor ID, product ID and (optionally) serial number: first in
/// <c>/sys/bus/usb-serial/devices</c> (walking up to the USB device's idVendor/idProduct/serial), then by the udev
/// names in <c>/dev/serial/by-id</c>.
/// </summary>
public static class UsbSerialResolver
{
    /// <summary>Returns <c>/dev/ttyXXX</c> of the matching adapter.</summary>
    /// <exception cref="IOException">No adapter, or more than one without a serial number to tell them apart.</exception>
    public static string Resolve(ushort vendor, ushort product, string? serial, string sysRoot = "/sys", string devRoot = "/dev")
    {
        var matches = new List<string>();
        var devices = Path.Combine(sysRoot, "bus", "usb-serial", "devices");
        if (Directory.Exists(devices))
        {
            foreach (var entry in Directory.GetFileSystemEntries(devices).Order(StringComparer.Ordinal))
            {
                var tty = Path.GetFileName(entry);
                var dir = new DirectoryInfo(entry).ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? entry;
                for (var d = new DirectoryInfo(dir); d is not null; d = d.Parent)
                {
                    var vid = Path.Combine(d.FullName, "idVendor");
                    if (!File.Exists(vid))
                    {
                        continue;
                    }

                    if (Hex(vid) == vendor && Hex(Path.Combine(d.FullName, "idProduct")) == product &&
                        (serial is null || ReadTrim(Path.Combine(d.FullName, "serial")) == serial))
                    {
                        matches.Add(Path.Combine(devRoot, tty));
                    }

                    break;
                }
            }
        }

        if (matches.Count == 0)
        {
            var byId = Path.Combine(devRoot, "serial", "by-id");
            if (Directory.Exists(byId))
            {
                foreach (var link in Directory.GetFileSystemEntries(byId).Order(StringComparer.Ordinal))
                {
                    var name = Path.GetFileName(link);
                    if (name.StartsWith("usb-", StringComparison.Ordinal) && (serial is null || name.Contains("_" + serial + "-", StringComparison.Ordinal)))
                    {
                        matches.Add(new FileInfo(link).ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? link);
                    }
                }

                // by-id names carry vendor/product names, not IDs: accept them only when the serial number pins the device.
                if (serial is null && matches.Count > 0)
                {
                    matches.Clear();
                }
            }
        }

        var wanted = $"usb:{vendor:x4}:{product:x4}" + (serial is null ? string.Empty : ":" + serial);
        return matches.Count switch
        {
            1 => matches[0],
            0 => throw new IOException($"no USB-serial adapter matches {wanted} (looked in {devices} and {Path.Combine(devRoot, "serial", "by-id")})"),
            _ => throw new IOException($"{matches.Count} adapters match {wanted} ({string.Join(", ", matches)}); add the serial number"),
        };
    }

    private static ushort? Hex(string file) =>
        ushort.TryParse(ReadTrim(file), NumberStyles.HexNumber, CultureInfo.InvariantCulture, out var v) ? v : null;

    private static string? ReadTrim(string file) => File.Exists(file) ? File.ReadAllText(file).Trim() : null;
}
