using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch;
using RobotControl.Plugins.Touch.Backends;
using RobotControl.Plugins.Touch.Simulation;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Touch.Tests;

public sealed class TouchTests
{
    /// <summary>A hand moving 10 mm along x in one second, then at rest at x = 10 mm up to 3 s.</summary>
    internal static HandScript Script() => HandScript.Parse(
        [
            "# a hand moving 10 mm along x in one second, clutch pressed from 0.5 s",
            "time_s,x_mm,y_mm,z_mm,roll_rad,pitch_rad,yaw_rad,button1,button2",
            "0,0,0,0,0,0,0,0,0",
            "0.5,5,0,0,0,0,0,1,0",
            "1,10,0,0,0.2,0,0,1,0",
            "3,10,0,0,0.2,0,0,0,0",
        ],
        "test");

    [Fact]
    public void The_simulated_touch_follows_the_scripted_hand_and_buttons()
    {
        var touch = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), new SimulatedTouchBackend(Script(), new HandModel(0.25, 0.2, 0.01), 3.3)));
        touch.Start().Tick(3100);

        Assert.Equal(10.0, touch["x"], 1);
        Assert.Equal(0.2, touch["roll"], 6);
        Assert.Equal(0.0, touch["button1"]);

        var pressed = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), new SimulatedTouchBackend(Script(), new HandModel(0.25, 0.2, 0.01), 3.3)));
        pressed.Start().Tick(700);
        Assert.Equal(1.0, pressed["button1"]);
    }

    [Fact]
    public void A_force_sent_to_the_device_visibly_pushes_the_handle_against_the_hand()
    {
        var touch = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), new SimulatedTouchBackend(Script(), new HandModel(0.25, 0.2, 0.01), 3.3)));
        touch.Start().Tick(2000); // hand at rest at x = 10

        touch.Set(("force_x", -1.0), ("force_z", 2.0)).Tick(800);

        // Static deflection F / k: -1 N / 0.2 N/mm = -5 mm in x, +10 mm in z.
        Assert.Equal(5.0, touch["x"], 1);
        Assert.Equal(10.0, touch["z"], 1);

        touch.Set(("force_x", double.NaN), ("force_z", 50)).Tick(800);
        Assert.Equal(10.0, touch["x"], 1); // non-finite force: dropped
    }

    [Fact]
    public void Excessive_forces_are_limited_to_the_devices_maximum()
    {
        var backend = new SimulatedTouchBackend(Script(), new HandModel(0.25, 0.2, 0.01), 3.3);
        backend.Open();
        TouchSample sample = default;
        for (var k = 0; k < 3000; k++)
        {
            sample = backend.Exchange(2 + (k * 0.001), new TouchForce(0, 100, 0));
        }

        Assert.Equal(3.3 / 0.2, sample.YMm, 1);
    }
}

public sealed class TouchRecordingTests
{
    [Fact]
    public void A_recorded_touch_session_replays_as_the_hand()
    {
        var script = HandScript.Parse(
            [
                "time_s,touch_right.x,touch_right.y,touch_right.z,touch_right.roll,touch_right.pitch,touch_right.yaw,touch_right.button1,touch_right.button2,other.v",
                "0,1,2,3,0,0,0,0,0,9",
                "1,11,2,3,0,0,0.5,1,0,9",
            ],
            "recording",
            "touch_right.");
        Span<double> pose = stackalloc double[6];
        Span<double> velocity = stackalloc double[3];
        var hint = 0;

        script.Sample(0.5, pose, velocity, out _, out _, ref hint);
        Assert.Equal(6.0, pose[0], 9);
        Assert.Equal(0.25, pose[5], 9);
        Assert.Equal(10.0, velocity[0], 9);
        script.Sample(1.0, pose, velocity, out var button1, out _, ref hint);
        Assert.True(button1);
    }
}
