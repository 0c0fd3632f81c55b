using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch.Backends;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Touch.Tests;

/// <summary>The plug-in between its ports and a back end: every reading reaches its output, the force and its enable reach the device.</summary>
public sealed class TouchPluginPortsTests
{
    [Fact]
    public void Every_field_of_a_reading_reaches_its_output()
    {
        var backend = new RecordingBackend(new TouchSample(1.5, -2.5, 3.5, 0.1, -0.2, 0.3, Button1: false, Button2: true, AgeMs: 7));
        var touch = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), backend));
        touch.Tick();

        Assert.Equal(
            [1.5, -2.5, 3.5, 0.1, -0.2, 0.3, 0, 1, 7],
            new[] { "x", "y", "z", "roll", "pitch", "yaw", "button1", "button2", "sample_age_ms" }.Select(o => touch[o]));
    }

    [Theory]
    [InlineData(0.0, false)]
    [InlineData(0.49, false)]
    [InlineData(0.5, true)] // the enable is a run level wired as 0 or 1: half-way counts as on
    [InlineData(1.0, true)]
    public void The_force_and_its_enable_reach_the_device(double enable, bool enabled)
    {
        var backend = new RecordingBackend(default);
        var touch = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), backend));
        touch.Set(("force_x", 0.25), ("force_y", -0.5), ("force_z", 1), ("force_enable", enable)).Tick();

        Assert.Equal(new TouchForce(0.25, -0.5, 1, enabled), backend.LastForce);
    }

    [Fact]
    public void A_missing_back_end_is_refused()
    {
        Assert.Throws<ArgumentNullException>(() => new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("t"), (ITouchBackend)null!));
    }

    private sealed class RecordingBackend(TouchSample reading) : ITouchBackend
    {
        public TouchForce LastForce { get; private set; }

        public string Description => "recording";

        public void Open()
        {
        }

        public TouchSample Exchange(double timeSeconds, in TouchForce force)
        {
            LastForce = force;
            return reading;
        }

        public void Dispose()
        {
        }
    }
}
