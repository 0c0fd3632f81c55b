using System.Globalization;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// The latency timer of a USB-serial adapter (FTDI: <c>/sys/class/tty/&lt;tty&gt;/device/latency_timer</c>, 16 ms by
/// default): how long the adapter holds a partly filled packet before sending it to the host. Every reply on the bus
/// waits this long at the adapter unless it is lowered; 1 ms is the practice for Dynamixel-style buses (U2D2).
/// </summary>
public static class LatencyTimer
{
    /// <summary>The sysfs file of <paramref name="device"/>'s latency timer (null: the device has none).</summary>
    public static string? File(string device, string sysRoot = "/sys")
    {
        ArgumentNullException.ThrowIfNull(device);
        if (!System.IO.File.Exists(device))
        {
            return null; // opening it will say so
        }

        var name = Path.GetFileName(new FileInfo(device).ResolveLinkTarget(returnFinalTarget: true)?.FullName ?? device);
        var path = Path.Combine(sysRoot, "class", "tty", name, "device", "latency_timer");
        return System.IO.File.Exists(path) ? path : null;
    }

    /// <summary>The latency timer in ms (null: none, or unreadable).</summary>
    public static int? Read(string device, string sysRoot = "/sys") =>
        File(device, sysRoot) is { } path && int.TryParse(System.IO.File.ReadAllText(path).Trim(), NumberStyles.None, CultureInfo.InvariantCulture, out var ms) ? ms : null;

    /// <summary>Sets the latency timer to 1 ms where the device has one and the file is writable; returns the value now (null: none).</summary>
    public static int? TrySetOneMs(string device, string sysRoot = "/sys")
    {
        if (File(device, sysRoot) is not { } path)
        {
            return null;
        }

        try
        {
            if (Read(device, sysRoot) != 1)
            {
                System.IO.File.WriteAllText(path, "1");
            }
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            // Not writable (no permission): the doctor command reports it and says how to change it.
        }

        return Read(device, sysRoot);
    }
}
