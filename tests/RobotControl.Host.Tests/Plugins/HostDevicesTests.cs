using RobotControl.Host.Plugins;
using RobotControl.Plugins.Sdk;

namespace RobotControl.Host.Tests.Plugins;

public sealed class HostDevicesTests
{
    [Fact]
    public void The_host_opens_devices_for_plug_ins_and_a_stand_alone_context_says_it_cannot()
    {
        Assert.ThrowsAny<FormatException>(() => HostDevices.Open("nonsense"));

        var alone = PluginContext.Standalone("pedals");
        var error = Assert.Throws<InvalidOperationException>(() => alone.OpenDevice("serial:/dev/ttyUSB1"));
        Assert.Equal("plug-in instance 'pedals': this host opens no devices (transport 'serial:/dev/ttyUSB1')", error.Message);

        var hosted = alone with { DeviceOpener = HostDevices.Open };
        Assert.ThrowsAny<FormatException>(() => hosted.OpenDevice("nonsense"));
    }
}
