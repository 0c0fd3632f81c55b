using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Conditioning;

/// <summary>Thresholds, the dead-man clutch, the first tick and axis inversions: the edges mutation testing found open.</summary>
public sealed class ConditioningEdgeTests
{
    [Fact]
    public void The_clutch_engages_at_the_threshold_itself_and_not_just_below()
    {
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings { Threshold = 0.5 }, PluginContext.Standalone("c")));
        clutch.Set(("x", 1), ("clutch", 0.4999)).Tick();
        Assert.Equal(0.0, clutch["engaged"]);

        clutch.Set(("x", 2), ("clutch", 0.5)).Tick();
        Assert.Equal(1.0, clutch["engaged"]);
        Assert.Equal(1.0, clutch["x"]); // held where the released tick left it
    }

    [Fact]
    public void A_dead_man_clutch_holds_while_the_input_is_below_the_threshold()
    {
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings { Inverted = true, Threshold = 0.5 }, PluginContext.Standalone("c")));
        clutch.Set(("x", 1), ("clutch", 1)).Tick();
        Assert.Equal((0.0, 1.0), (clutch["engaged"], clutch["x"]));

        clutch.Set(("x", 3), ("clutch", 0.5)).Tick(); // at the threshold: not below, so still released
        Assert.Equal((0.0, 3.0), (clutch["engaged"], clutch["x"]));

        clutch.Set(("x", 7), ("clutch", 0)).Tick(); // let go of the switch: held
        Assert.Equal((1.0, 3.0), (clutch["engaged"], clutch["x"]));

        clutch.Set(("x", 8), ("clutch", 1)).Tick(); // pressed again: resumes from 3 without a jump
        clutch.Set(("x", 9)).Tick();
        Assert.Equal((0.0, 4.0), (clutch["engaged"], clutch["x"]));
    }

    [Fact]
    public void A_clutch_held_from_the_first_tick_starts_at_the_device_position()
    {
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings(), PluginContext.Standalone("c")));
        clutch.Set(("x", 5), ("yaw", 0.25), ("clutch", 1)).Tick();
        Assert.Equal((5.0, 0.25), (clutch["x"], clutch["yaw"]));

        clutch.Set(("x", 9), ("yaw", 0.75)).Tick(3);
        Assert.Equal((5.0, 0.25), (clutch["x"], clutch["yaw"]));

        clutch.Set(("clutch", 0)).Tick();
        clutch.Set(("x", 10), ("yaw", 1)).Tick();
        Assert.Equal((6.0, 0.5), (clutch["x"], clutch["yaw"]));
    }

    [Theory]
    [InlineData(true, false, false, -2.0, 3.0, 4.0)]
    [InlineData(false, true, false, 2.0, -3.0, 4.0)]
    [InlineData(false, false, true, 2.0, 3.0, -4.0)]
    public void Homing_inverts_each_device_axis_on_its_own(bool invertX, bool invertY, bool invertZ, double x, double y, double z)
    {
        // No rotation: robot = origin + S (device - home), S the inversion; worked out by hand.
        var settings = new HomingSettings { OriginXMm = 10, OriginYMm = 20, OriginZMm = 30, DeviceHomeXMm = 1, DeviceHomeYMm = 1, DeviceHomeZMm = 1, InvertX = invertX, InvertY = invertY, InvertZ = invertZ };
        var homing = new PluginDriver(new HomingPlugin(settings, PluginContext.Standalone("h")));

        homing.Set(("x", 3), ("y", 4), ("z", 5)).Tick();

        var (rx, ry, rz) = homing.Xyz();
        Assert.Equal(10 + x, rx, 12);
        Assert.Equal(20 + y, ry, 12);
        Assert.Equal(30 + z, rz, 12);
    }

    [Fact]
    public void Homing_pitch_turns_device_x_into_robot_minus_z()
    {
        // Pitch 90 deg about y: R_y = [[0,0,1],[0,1,0],[-1,0,0]], so device x -> robot -z and device z -> robot x.
        var homing = new PluginDriver(new HomingPlugin(new HomingSettings { PitchDeg = 90 }, PluginContext.Standalone("h")));

        homing.Set(("x", 2), ("y", 0), ("z", 0)).Tick();
        var (x1, y1, z1) = homing.Xyz();
        Assert.Equal((0.0, 0.0, -2.0), (Math.Round(x1, 12), Math.Round(y1, 12), Math.Round(z1, 12)));

        homing.Set(("x", 0), ("z", 3)).Tick();
        var (x2, y2, z2) = homing.Xyz();
        Assert.Equal((3.0, 0.0, 0.0), (Math.Round(x2, 12), Math.Round(y2, 12), Math.Round(z2, 12)));
    }

    [Fact]
    public void Homing_passes_an_orientation_through_an_identity_frame_unchanged()
    {
        var homing = new PluginDriver(new HomingPlugin(new HomingSettings(), PluginContext.Standalone("h")));

        homing.Set(("roll", 0.1), ("pitch", -0.2), ("yaw", 0.3)).Tick();

        Assert.Equal(0.1, homing["roll"], 12);
        Assert.Equal(-0.2, homing["pitch"], 12);
        Assert.Equal(0.3, homing["yaw"], 12);
    }
}
