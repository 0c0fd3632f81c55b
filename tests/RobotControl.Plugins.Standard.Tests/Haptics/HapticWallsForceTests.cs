using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Haptics;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Haptics;

public sealed class HapticWallsForceTests
{
    // A device displacement d moves the robot by ratio * d, so a workspace stiffness felt at the handle is the robot's
    // divided by the ratio: F_device = gain * F_robot / ratio (then expressed in the device frame). Ratio 0.25 and
    // gain 2 make the factor 8; the expected values below are worked out by hand.
    [Fact]
    public void The_force_is_the_workspace_force_times_gain_over_ratio_in_an_aligned_frame()
    {
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { ScaleRatio = 0.25, Gain = 2, MaxForceN = 10 }, PluginContext.Standalone("w")));
        walls.Set(("fx", 0.1), ("fy", -0.05), ("fz", 0.02)).Tick();
        Assert.Equal(0.8, walls["fx"], 12);
        Assert.Equal(-0.4, walls["fy"], 12);
        Assert.Equal(0.16, walls["fz"], 12);
    }

    [Fact]
    public void The_force_is_the_workspace_force_times_gain_over_ratio_in_a_rolled_frame()
    {
        // Roll 90 deg (as the homing plug-in): robot x -> device x, robot z -> device y, robot y -> device -z.
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { RollDeg = 90, ScaleRatio = 0.25, Gain = 2, MaxForceN = 10 }, PluginContext.Standalone("w")));
        walls.Set(("fx", 0.1), ("fy", -0.05), ("fz", 0.02)).Tick();
        Assert.Equal(0.8, walls["fx"], 12);
        Assert.Equal(0.16, walls["fy"], 12);
        Assert.Equal(0.4, walls["fz"], 12);
    }

    [Fact]
    public void The_force_is_the_workspace_force_times_gain_over_ratio_in_a_yawed_frame()
    {
        // Yaw 90 deg: the device frame is the robot's turned about z, R = Rz(90). The device force is R^T f: robot y ->
        // device x, robot x -> device -y, z unchanged; times gain 2 over ratio 0.25.
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { YawDeg = 90, ScaleRatio = 0.25, Gain = 2, MaxForceN = 10 }, PluginContext.Standalone("w")));
        walls.Set(("fx", 0.1), ("fy", -0.05), ("fz", 0.02)).Tick();
        Assert.Equal(-0.4, walls["fx"], 12);
        Assert.Equal(-0.8, walls["fy"], 12);
        Assert.Equal(0.16, walls["fz"], 12);
    }

    [Fact]
    public void The_scale_ratio_input_sets_the_ratio_from_the_next_tick_and_out_of_range_values_are_ignored()
    {
        // Starts at the setting (0.25: factor 8 with gain 2); the scaling's ratio output changes it to 0.5 (factor 4).
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { ScaleRatio = 0.25, Gain = 2, MaxForceN = 10 }, PluginContext.Standalone("w")));
        walls.Set(("fx", 0.1), ("fy", -0.05), ("fz", 0.02)).Tick();
        Assert.Equal(0.8, walls["fx"], 12);

        walls.Set(("scale_ratio", 0.5)).Tick();
        Assert.Equal(0.4, walls["fx"], 12);
        Assert.Equal(-0.2, walls["fy"], 12);
        Assert.Equal(0.08, walls["fz"], 12);

        foreach (var bad in new[] { 0.0, 0.009, -0.5, 10.5, double.NaN, double.PositiveInfinity })
        {
            walls.Set(("scale_ratio", bad)).Tick();
            Assert.Equal(0.4, walls["fx"], 12);
        }

        walls.Set(("scale_ratio", 10)).Tick(); // the range's end is a ratio too
        Assert.Equal(0.02, walls["fx"], 12);
    }
}
