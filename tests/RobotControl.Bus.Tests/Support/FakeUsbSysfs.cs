namespace RobotControl.Bus.Tests.Support;

/// <summary>
/// A temporary directory laid out like Linux sysfs for one FTDI USB-RS485 adapter (0403:6001, serial A50285BI) whose
/// tty is ttyUSB3, so the usb: transport can be resolved without hardware. Deleted on dispose.
/// </summary>
internal sealed class FakeUsbSysfs : IDisposable
{
    public const string TtyName = "ttyUSB3";

    private readonly DirectoryInfo _root;

    public FakeUsbSysfs()
    {
        _root = Directory.CreateTempSubdirectory("usbsys");
        var usbDevice = Directory.CreateDirectory(Path.Combine(SysPath, "devices", "usb1", "1-1"));
        File.WriteAllText(Path.Combine(usbDevice.FullName, "idVendor"), "0403\n");
        File.WriteAllText(Path.Combine(usbDevice.FullName, "idProduct"), "6001\n");
        File.WriteAllText(Path.Combine(usbDevice.FullName, "serial"), "A50285BI\n");
        var iface = Directory.CreateDirectory(Path.Combine(usbDevice.FullName, "1-1:1.0", TtyName));
        var devices = Directory.CreateDirectory(Path.Combine(SysPath, "bus", "usb-serial", "devices"));
        Directory.CreateSymbolicLink(Path.Combine(devices.FullName, TtyName), iface.FullName);
    }

    /// <summary>The temporary directory holding the fake tree.</summary>
    public string Root => _root.FullName;

    /// <summary>The fake /sys.</summary>
    public string SysPath => Path.Combine(_root.FullName, "sys");

    public void Dispose() => _root.Delete(recursive: true);
}
