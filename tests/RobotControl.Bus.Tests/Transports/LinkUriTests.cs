using RobotControl.Bus.Tests.Support;
using RobotControl.Bus.Transports;

namespace RobotControl.Bus.Tests.Transports;

public sealed class LinkUriTests
{
    [Fact]
    public void Serial_with_options()
    {
        var uri = LinkUri.Parse("serial:/dev/ttyUSB0?baud=3000000&parity=even&rs485=rts");
        Assert.Equal(LinkKind.Serial, uri.Kind);
        Assert.Equal("/dev/ttyUSB0", uri.Target);
        Assert.Equal(3_000_000, uri.BaudRate);
        Assert.Equal(SerialParity.Even, uri.Parity);
        Assert.Equal(Rs485DriverEnable.Rts, uri.Rs485);
        Assert.Equal(Rs485DriverEnable.Auto, LinkUri.Parse("serial:/dev/ttyUSB0").Rs485);
    }

    [Fact]
    public void Usb_tcp_and_virtual()
    {
        Assert.Equal(((ushort)0x0403, (ushort)0x6001, "A50285BI"), LinkUri.Parse("usb:0403:6001:A50285BI").UsbIds());
        Assert.Equal(((ushort)0x0403, (ushort)0x6001, (string?)null), LinkUri.Parse("usb:0403:6001").UsbIds());
        Assert.Equal(("127.0.0.1", 4000), LinkUri.Parse("tcp:127.0.0.1:4000").TcpEndpoint());
        var v = LinkUri.Parse("virtual:hardware/robots/lb-1.0.json");
        Assert.Equal(LinkKind.Virtual, v.Kind);
        Assert.Equal(LinkUri.DefaultBaud, v.BaudRate);
    }

    [Theory]
    [InlineData("ttyUSB0", "expected kind:target")]
    [InlineData("", "expected kind:target")]
    [InlineData("   ", "expected kind:target")]
    [InlineData("modem:/dev/x", "unknown kind")]
    [InlineData("serial:/dev/x?baud=fast", "baud")]
    [InlineData("serial:/dev/x?speed=9600", "unknown option")]
    [InlineData("tcp:localhost", "port")]
    [InlineData("usb:xyz:6001", "vendor")]
    [InlineData("serial:", "empty")]
    [InlineData("serial:/dev/x?rs485=true", "auto (the adapter switches direction itself")]
    public void Malformed_strings_say_what_is_wrong(string text, string fragment)
    {
        var ex = Assert.Throws<FormatException>(() => LinkUri.Parse(text));
        Assert.Contains(fragment, ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Usb_adapter_is_resolved_from_sysfs()
    {
        using var fake = new FakeUsbSysfs();
        var sys = fake.SysPath;
        Assert.Equal("/dev/ttyUSB3", UsbSerialResolver.Resolve(0x0403, 0x6001, "A50285BI", sys, "/dev"));
        Assert.Equal("/dev/ttyUSB3", UsbSerialResolver.Resolve(0x0403, 0x6001, null, sys, "/dev"));
        var ex = Assert.Throws<IOException>(() => UsbSerialResolver.Resolve(0x0403, 0x6001, "OTHER", sys, "/nonexistent"));
        Assert.Contains("usb:0403:6001:OTHER", ex.Message, StringComparison.Ordinal);
    }
}
