using System.Diagnostics;
using RobotControl.Bus.Tests.Support;
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
        using var fake = new FakeUsbSysfs();
        var dev = Directory.CreateDirectory(Path.Combine(fake.Root, "dev"));
        File.CreateSymbolicLink(Path.Combine(dev.FullName, FakeUsbSysfs.TtyName), pty.SlavePath);

        using var link = LinkFactory.Open(LinkUri.Parse("usb:0403:6001:A50285BI?baud=2000000"), fake.SysPath, dev.FullName);

        var serial = Assert.IsType<SerialLink>(link);
        Assert.Contains(Path.Combine(dev.FullName, FakeUsbSysfs.TtyName), serial.Description, StringComparison.Ordinal);
        Assert.Equal(2_000_000, link.BaudRate);
        AssertCarriesBytes(pty, link);
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
