using RobotControl.Host.Plugins;

namespace RobotControl.Cli.Tests;

public sealed class ShippedPluginsTests
{
    [Fact]
    public void The_catalogue_holds_the_shipped_plug_ins_and_opens_devices_the_hosts_way()
    {
        var catalog = ShippedPlugins.Catalog();
        Assert.Empty(catalog.Problems);
        Assert.All(new[] { "clutch", "touch", "coppeliasim", "foot_pedals", "link_out", "link_in" }, name => Assert.NotNull(catalog.Find(name)));
        Assert.Equal(HostDevices.Open, catalog.DeviceOpener);
        Assert.ThrowsAny<FormatException>(() => catalog.DeviceOpener!("nonsense"));
    }
}
