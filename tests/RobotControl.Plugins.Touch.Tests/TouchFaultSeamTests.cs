using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Plugins.Touch.Backends;
using RobotControl.Plugins.Touch.Simulation;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Touch.Tests;

/// <summary>Faults injected through the SDK's <see cref="IFaultInjectable"/> seam, as the harness does: no cast to the Touch or its back end.</summary>
public sealed class TouchFaultSeamTests
{
    /// <summary>A simulated Touch whose hand is at rest at x = 10 mm (2 s into <see cref="TouchTests.Script"/>).</summary>
    private static PluginDriver AtRest()
    {
        var backend = new SimulatedTouchBackend(TouchTests.Script(), new HandModel(0.25, 0.2, 0.01), 3.3);
        return new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("touch_right"), backend)).Start().Tick(2000);
    }

    private static IFaultInjectable Seam(PluginDriver driver) => Assert.IsAssignableFrom<IFaultInjectable>(driver.Plugin);

    [Fact]
    public void A_simulated_touch_takes_both_device_faults()
    {
        var seam = Seam(AtRest());

        Assert.True(seam.CanTake(DeviceFaultKind.Jump));
        Assert.True(seam.CanTake(DeviceFaultKind.Stale));
    }

    [Fact]
    public void A_jump_through_the_seam_is_reported_as_a_speed_no_hand_makes_and_the_pose_keeps_the_last_plausible_reading()
    {
        var touch = AtRest();
        var before = touch.Xyz();
        Assert.Equal(10.0, before.X, 1);
        Assert.Equal(0.0, touch["speed_mm_s"], 6);

        Seam(touch).Inject(DeviceFault.Jump(50));
        touch.Tick();

        // 50 mm in one 1 ms reading: 50 m/s at the device, past the 2 m/s limit; nothing downstream sees the jump.
        Assert.Equal(50_000, touch["speed_mm_s"], 0);
        Assert.Equal(before, touch.Xyz());

        // The device keeps its offset: the next reading is plausible again (from the jumped one) and goes through; the
        // robot's supervisor has put the run at PEDAL_UP, and the clutch re-offsets the master before it drives again.
        touch.Tick();
        Assert.Equal(0.0, touch["speed_mm_s"], 6);
        Assert.Equal(before.X + 50, touch["x"], 3);
        Assert.Equal(before.Y, touch["y"], 3);
    }

    [Fact]
    public void A_stale_fault_through_the_seam_holds_the_reading_and_its_age_grows()
    {
        var touch = AtRest();
        var before = touch["x"];
        Assert.Equal(0.0, touch["sample_age_ms"]);

        Seam(touch).Inject(DeviceFault.Stale);
        touch.Tick(40);

        Assert.Equal(40.0, touch["sample_age_ms"], 6);
        Assert.Equal(before, touch["x"]);
    }

    [Fact]
    public void A_touch_whose_back_end_takes_no_faults_says_so_and_refuses_them()
    {
        var touch = new PluginDriver(new TouchPlugin(new TouchSettings { Script = "x.csv" }, PluginContext.Standalone("touch_real"), new QuietBackend()));
        var seam = Seam(touch);

        Assert.False(seam.CanTake(DeviceFaultKind.Jump));
        Assert.False(seam.CanTake(DeviceFaultKind.Stale));
        var error = Assert.Throws<ArgumentException>(() => seam.Inject(DeviceFault.Stale));
        Assert.StartsWith("Touch 'touch_real' (quiet) cannot take a stale fault", error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_jump_that_is_not_finite_is_refused_by_the_back_end()
    {
        var touch = AtRest();
        var before = touch["x"];

        Assert.Throws<ArgumentOutOfRangeException>(() => Seam(touch).Inject(DeviceFault.Jump(double.NaN)));
        touch.Tick();
        Assert.Equal(before, touch["x"], 3);
    }

    private sealed class QuietBackend : ITouchBackend
    {
        public string Description => "quiet";

        public void Open()
        {
        }

        public TouchSample Exchange(double timeSeconds, in TouchForce force) => default;

        public void Dispose()
        {
        }
    }
}
