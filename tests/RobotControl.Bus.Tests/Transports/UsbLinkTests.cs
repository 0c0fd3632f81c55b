using System.Diagnostics;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Bus.Tests.Transports;

/// <summary>usb: transports resolve to a device node and open through the serial link; a pty stands in for the adapter.</summary>
public sealed class UsbLinkTests
{
    [Fact]
    public void A_usb_transport_found_in_sysfs_opens_as_serial()
    {
        using var pty = PseudoTerminal.Create();
        var root = Directory.CreateTempSubdirectory("usblink");
        try
        {
            var usbDevice = Directory.CreateDirectory(Path.Combine(root.FullName, "sys", "devices", "usb1", "1-1"));
            File.WriteAllText(Path.Combine(usbDevice.FullName, "idVendor"), "0403\n");
            File.WriteAllText(Path.Combine(usbDevice.FullName, "idProduct"), "6001\n");
            File.WriteAllText(Path.Combine(usbDevice.FullName, "serial"), "A50285BI\n");
            var iface = Directory.CreateDirectory(Path.Combine(usbDevice.FullName, "1-1:1.0", "ttyUSB3"));
            var devices = Directory.CreateDirectory(Path.Combine(root.FullName, "sys", "bus", "usb-serial", "devices"));
            Directory.CreateSymbolicLink(Path.Combine(devices.FullName, "ttyUSB3"), iface.FullName);
            var dev = Directory.CreateDirectory(Path.Combine(root.FullName, "dev"));
            File.CreateSymbolicLink(Path.Combine(dev.FullName, "ttyUSB3"), pty.SlavePath);

            using var link = LinkFactory.Open(LinkUri.Parse("usb:0403:6001:A50285BI?baud=2000000"), Path.Combine(root.FullName, "sys"), dev.FullName);

            var serial = Assert.IsType<SerialLink>(link);
            Assert.Contains(Path.Combine(dev.FullName, "ttyUSB3"), serial.Description, StringComparison.Ordinal);
            Assert.Equal(2_000_000, link.BaudRate);
            AssertCarriesBytes(pty, link);
        }
        finally
        {
            root.Delete(recursive: true);
        }
    }

    [Fact]
    public void A_usb_transport_found_by_id_opens_as_serial()
    {
        using var pty = PseudoTerminal.Create();
        var root = Directory.CreateTempSubdirectory("usblink");
        try
        {
            var byId = Directory.CreateDirectory(Path.Combine(root.FullName, "dev", "serial", "by-id"));
            File.CreateSymbolicLink(Path.Combine(byId.FullName, "usb-FTDI_USB-RS485_Cable_A50285BI-if00-port0"), pty.SlavePath);

            using var link = LinkFactory.Open(LinkUri.Parse("usb:0403:6001:A50285BI"), Path.Combine(root.FullName, "sys"), Path.Combine(root.FullName, "dev"));

            Assert.Contains(pty.SlavePath, link.Description, StringComparison.Ordinal);
            AssertCarriesBytes(pty, link);
        }
        finally
        {
            root.Delete(recursive: true);
        }
    }

    private static void AssertCarriesBytes(PseudoTerminal pty, IByteLink link)
    {
        link.Write([0xFF, 0xFF, 0xFD, 0x00]);
        pty.Write([0x42]);
        var rx = new byte[8];
        var got = 0;
        var start = Stopwatch.GetTimestamp();
        while (got < 4 && Stopwatch.GetElapsedTime(start) < TimeSpan.FromSeconds(2))
        {
            got += pty.Read(rx.AsSpan(got), TimeSpan.FromMilliseconds(100));
        }

        Assert.Equal(new byte[] { 0xFF, 0xFF, 0xFD, 0x00 }, rx[..got]);
        Assert.Equal(1, link.Read(rx, TimeSpan.FromSeconds(2)));
        Assert.Equal(0x42, rx[0]);
    }
}
