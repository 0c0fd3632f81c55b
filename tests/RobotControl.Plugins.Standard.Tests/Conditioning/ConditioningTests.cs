using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Conditioning;

public sealed class ConditioningTests
{
    private static PluginContext Context(string name) => PluginContext.Standalone(name);

    [Fact]
    public void Scaling_multiplies_displacement_about_the_reference_point()
    {
        var scaling = new PluginDriver(new ScalingPlugin(new ScalingSettings { Ratio = 0.25, ReferenceXMm = 100, ReferenceYMm = -20, ReferenceZMm = 5 }, Context("s")));

        scaling.Set(("x", 100), ("y", -20), ("z", 5)).Tick();
        Assert.Equal((100.0, -20.0, 5.0), scaling.Xyz()); // the reference point is a fixed point

        scaling.Set(("x", 140), ("y", 0), ("z", -15)).Tick();
        Assert.Equal((110.0, -15.0, 0.0), scaling.Xyz());
    }

    [Fact]
    public void The_ratio_input_changes_the_scale_at_the_next_tick_and_out_of_range_values_are_ignored()
    {
        var scaling = new PluginDriver(new ScalingPlugin(new ScalingSettings { Ratio = 0.5, ReferenceXMm = 100 }, Context("s")));
        Assert.Equal(0.5, scaling["ratio"]); // the ratio output starts at the setting, before the first tick
        scaling.Set(("x", 140), ("y", 0), ("z", 0)).Tick();
        Assert.Equal(120.0, scaling.Xyz().Item1);
        Assert.Equal(0.5, scaling["ratio"]);

        scaling.Set(("ratio", 0.25)).Tick();
        Assert.Equal(110.0, scaling.Xyz().Item1);
        Assert.Equal(0.25, scaling["ratio"]); // the ratio in effect, for the haptic walls

        // Outside the ratio setting's range (0.01..10) or not a number: the last good ratio stays.
        foreach (var bad in new[] { 0.0, -1, 11, double.NaN })
        {
            scaling.Set(("ratio", bad)).Tick();
            Assert.Equal(110.0, scaling.Xyz().Item1);
            Assert.Equal(0.25, scaling["ratio"]);
        }
    }

    [Theory]
    [InlineData(0.01, 100.4)] // the ends of the ratio setting's range are ratios too
    [InlineData(10, 500)]
    public void The_ratio_input_takes_the_ends_of_its_range(double ratio, double x)
    {
        var scaling = new PluginDriver(new ScalingPlugin(new ScalingSettings { Ratio = 0.5, ReferenceXMm = 100 }, Context("s")));
        scaling.Set(("x", 140), ("y", 0), ("z", 0), ("ratio", ratio)).Tick();
        Assert.Equal(x, scaling.Xyz().Item1, 9);
        Assert.Equal(ratio, scaling["ratio"]);
    }

    [Fact]
    public void Homing_maps_the_device_home_to_the_origin_through_the_rotation()
    {
        // roll 90 deg: device y (up) becomes robot z (up), device z (toward the user) becomes robot -y.
        var homing = new PluginDriver(new HomingPlugin(new HomingSettings { OriginXMm = 100, OriginYMm = 30, OriginZMm = -40, DeviceHomeZMm = 10, RollDeg = 90 }, Context("h")));

        homing.Set(("x", 0), ("y", 0), ("z", 10)).Tick();
        AssertClose((100, 30, -40), homing.Xyz());

        homing.Set(("x", 5), ("y", 7), ("z", 13)).Tick();
        AssertClose((105, 27, -33), homing.Xyz());
    }

    [Fact]
    public void Homing_mirrors_the_left_arm_in_the_robots_x_z_plane()
    {
        var settings = new HomingSettings { OriginXMm = 100, OriginYMm = 30, OriginZMm = -40, YawDeg = 20 };
        var right = new PluginDriver(new HomingPlugin(settings, Context("right")));
        var left = new PluginDriver(new HomingPlugin(settings with { Mirror = true }, Context("left")));

        foreach (var (x, y, z) in new[] { (10.0, 0.0, 0.0), (0.0, 10.0, 0.0), (3.0, -4.0, 12.0) })
        {
            right.Set(("x", x), ("y", y), ("z", z), ("roll", 0.1), ("pitch", 0.2), ("yaw", 0.3)).Tick();
            left.Set(("x", x), ("y", y), ("z", z), ("roll", 0.1), ("pitch", 0.2), ("yaw", 0.3)).Tick();

            var r = right.Xyz();
            var l = left.Xyz();
            Assert.Equal(r.X, l.X, 9);
            Assert.Equal(r.Y - 30, -(l.Y - 30), 9); // displacement along y is reflected about the origin
            Assert.Equal(r.Z, l.Z, 9);

            // A reflected orientation: roll and yaw change sign, pitch stays.
            Assert.Equal(right["roll"], -left["roll"], 9);
            Assert.Equal(right["pitch"], left["pitch"], 9);
            Assert.Equal(right["yaw"], -left["yaw"], 9);
        }
    }

    [Fact]
    public void Clutch_holds_the_target_while_pressed_and_resumes_without_a_jump()
    {
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings(), Context("c")));
        var trace = new List<double>();
        var device = 0.0;
        for (var k = 0; k < 300; k++)
        {
            device += 0.05; // the device moves steadily all along
            var pressed = k is >= 100 and < 200;
            clutch.Set(("x", device), ("y", -device), ("z", 2 * device), ("clutch", pressed ? 1 : 0)).Tick();
            trace.Add(clutch["x"]);
            if (pressed)
            {
                Assert.Equal(1.0, clutch["engaged"]);
            }
        }

        // While held the target does not move; the largest step anywhere is the device's own step (no jump).
        Assert.All(trace.Skip(100).Take(100), x => Assert.Equal(trace[99], x));
        Assert.True(trace.Zip(trace.Skip(1), (a, b) => Math.Abs(b - a)).Max() <= 0.05 + 1e-12);

        // After release the target moves with the device again, offset by the distance travelled while held.
        Assert.Equal(device - (101 * 0.05), trace[^1], 9); // 100 held ticks plus the release tick
        Assert.Equal(-(device - (101 * 0.05)), clutch["y"], 9);
    }

    private static void AssertClose((double X, double Y, double Z) expected, (double X, double Y, double Z) actual)
    {
        Assert.Equal(expected.X, actual.X, 9);
        Assert.Equal(expected.Y, actual.Y, 9);
        Assert.Equal(expected.Z, actual.Z, 9);
    }
}
