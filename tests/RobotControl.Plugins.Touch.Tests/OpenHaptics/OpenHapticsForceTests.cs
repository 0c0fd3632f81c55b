using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Haptics;
using RobotControl.Runtime.Graph;
using RobotControl.TestSupport;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

[Collection(FakeHdCollection.Name)]
public sealed class OpenHapticsForceTests
{
    public OpenHapticsForceTests() => FakeHdLibrary.Reset();

    private static double Magnitude((long Frame, double X, double Y, double Z, bool Enabled) f) => Math.Sqrt((f.X * f.X) + (f.Y * f.Y) + (f.Z * f.Z));

    [Fact]
    public void Force_is_clamped_to_the_devices_continuous_maximum_and_ramped_in()
    {
        FakeHdLibrary.SetLimits("right", 3.3, 0.88);
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings() with { MaxForceN = 2.0, ForceRampS = 0.2 }));
        touch.Set(("force_y", 5.0)).Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 500);
        }
        finally
        {
            touch.Plugin.Stop();
        }

        var forces = FakeHdLibrary.Forces("right");
        Assert.All(forces, f => Assert.True(f.Enabled && Magnitude(f) <= 0.88 + 1e-12 && f.X == 0 && f.Z == 0, $"frame {f.Frame}: {f}"));
        var pushing = forces.Where(f => f.Y > 0).ToList();
        Assert.InRange(pushing[0].Y, 0, 0.05); // the ramp starts near zero...
        Assert.Equal(0.88, pushing[^1].Y, 12); // ...and ends at the cap
        var rampFrames = pushing.First(f => f.Y >= 0.88 - 1e-12).Frame - pushing[0].Frame;
        Assert.InRange(rampFrames, 150, 260); // 0.2 s at 1 kHz, give or take a stall of the test's thread
    }

    [Fact]
    public void Forces_from_walls_and_damping_reach_the_device_clamped()
    {
        FakeHdLibrary.SetLimits("right", 3.3, 0.88);
        for (var k = 1; k <= 30; k++)
        {
            FakeHdLibrary.Key("right", 200 + (k * 10), 0, 0, k); // 1 mm every 10 ms along +z: 100 mm/s
        }

        // Staleness has its own test; here a loop thread starved for a few ms on a loaded machine must not zero the force.
        var touch = FakeTouch.Plugin(FakeTouch.Settings() with { ForceRampS = 0.05, StaleAfterMs = 250 });
        var walls = new HapticWallsPlugin(new HapticWallsSettings { MaxForceN = 2.0 }, PluginContext.Standalone("walls"));
        var damping = new ViscousDampingPlugin(new ViscousDampingSettings { DampingNsPerMm = 0.002, MaxForceN = 1.0 }, PluginContext.Standalone("damping"));
        var graph = new PluginGraph();
        graph.Add(touch);
        graph.Add(walls);
        graph.Add(damping);
        foreach (var a in new[] { "x", "y", "z" })
        {
            graph.Connect($"touch.{a}", $"damping.{a}");
            graph.Connect($"walls.f{a}", $"damping.f{a}_in");
            graph.Connect($"damping.f{a}", $"touch.force_{a}", delayed: true);
        }

        var program = graph.Compile();
        walls.SetInput("fx", -3.0); // a wall pushing back along -x, beyond the walls' own limit
        program.Start(Ticks.At(0));
        long tick = 0;
        try
        {
            FakeTouch.TickUntil(program, ref tick, () => FakeHdLibrary.Frames("right") >= 700);
        }
        finally
        {
            program.Stop();
        }

        Assert.Empty(program.Faults);
        var forces = FakeHdLibrary.Forces("right").Where(f => f.Frame <= 700).ToList(); // after the stop the device gets zero
        Assert.All(forces, f => Assert.True(Magnitude(f) <= 0.88 + 1e-12, $"frame {f.Frame}: {f}"));
        var moving = forces.Where(f => f.Frame is > 260 and < 500).ToList();
        Assert.Contains(moving, f => f.Z < -0.02); // damping opposes the motion along +z
        // The wall alone reaches the device clamped from 2 N to 0.88 N (at rest; while the loop thread is starved on a
        // loaded machine the damping's velocity estimate may add a transient z force, so not every frame is pure).
        Assert.Contains(forces, f => Math.Abs(f.X + 0.88) < 1e-3 && Math.Abs(f.Z) < 1e-3);
    }

    [Fact]
    public void Force_is_zero_while_the_loop_is_stale_and_ramps_in_again_after()
    {
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings() with { StaleAfterMs = 50, ForceRampS = 0.1 }));
        touch.Set(("force_x", 0.5)).Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 300);
            var paused = FakeHdLibrary.Frames("right");
            Thread.Sleep(400); // the loop stalls
            var resumed = FakeHdLibrary.Frames("right");
            FakeTouch.TickToFrame(touch, "right", resumed + 400);

            var forces = FakeHdLibrary.Forces("right");
            Assert.Contains(forces, f => f.Frame < paused && f.X == 0.5);
            Assert.All(forces.Where(f => f.Frame > paused + 55 && f.Frame < resumed), f => Assert.Equal(0.0, f.X));
            var after = forces.Where(f => f.Frame >= resumed && f.X > 0).ToList();
            Assert.InRange(after[0].X, 0, 0.05); // ramped in again
            Assert.Contains(after, f => f.X == 0.5);
        }
        finally
        {
            touch.Plugin.Stop();
        }
    }

    [Fact]
    public void Force_enable_at_zero_keeps_the_device_free_of_force()
    {
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings() with { StaleAfterMs = 250 }));
        touch.Set(("force_x", 0.5), ("force_enable", 0.0)).Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 200);
            var enabledAt = FakeHdLibrary.Frames("right");
            touch.Set(("force_enable", 1.0));
            FakeTouch.TickToFrame(touch, "right", enabledAt + 400);

            var forces = FakeHdLibrary.Forces("right");
            Assert.All(forces.Where(f => f.Frame < enabledAt), f => Assert.Equal(0.0, f.X));
            Assert.Contains(forces.Where(f => f.Frame > enabledAt + 300), f => Math.Abs(f.X - 0.5) < 1e-12); // ramped in
        }
        finally
        {
            touch.Plugin.Stop();
        }
    }

    [Fact]
    public void Calibration_not_ok_means_no_force_is_ever_sent_but_positions_arrive()
    {
        FakeHdLibrary.SetCalibration("right", FakeHdLibrary.CalibrationNeedsManualInput);
        FakeHdLibrary.Key("right", 0, 4, 5, 6);
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings()));
        touch.Set(("force_x", 0.5)).Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 300);
            touch.Tick();
            Assert.Equal((4.0, 5.0, 6.0), touch.Xyz());
        }
        finally
        {
            touch.Plugin.Stop();
        }

        Assert.Empty(FakeHdLibrary.Forces("right"));
        Assert.False(FakeHdLibrary.ForceOutputEverEnabled("right"));
    }
}
