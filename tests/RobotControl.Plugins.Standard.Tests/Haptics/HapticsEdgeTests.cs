using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Haptics;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Haptics;

/// <summary>Clamps on both sides, force pass-through, the velocity filter's step response, thresholds and sign settings.</summary>
public sealed class HapticsEdgeTests
{
    [Fact]
    public void The_velocity_filter_follows_a_first_order_step_response()
    {
        // Ticks of 1 ms, cut-off 30 Hz: alpha = 1 - exp(-2 pi 30 0.001) = 0.1717958. A handle moving 0.1 mm per tick
        // (100 mm/s) from the second tick on gives v1 = 100 alpha = 17.17958 mm/s and v2 = 100 (1 - (1 - alpha)^2)
        // = 31.40778 mm/s; with b = 0.01 N s/mm the force is -b v.
        var damping = new PluginDriver(new ViscousDampingPlugin(new ViscousDampingSettings { DampingNsPerMm = 0.01, VelocityFilterHz = 30, MaxForceN = 5 }, PluginContext.Standalone("d")));
        var plugin = (ViscousDampingPlugin)damping.Plugin;

        damping.Set(("x", 4)).Tick();
        Assert.Equal(0.0, plugin.Velocity[0]); // the first tick only primes the derivative
        Assert.Equal(0.0, damping["fx"]);

        damping.Set(("x", 4.1)).Tick();
        Assert.Equal(17.17958, plugin.Velocity[0], 5);
        Assert.Equal(-0.1717958, damping["fx"], 6);

        damping.Set(("x", 4.2)).Tick();
        Assert.Equal(31.40778, plugin.Velocity[0], 5);
        Assert.Equal(-0.3140778, damping["fx"], 6);
    }

    [Fact]
    public void Damping_is_clamped_on_both_sides_and_added_to_the_incoming_force()
    {
        var damping = new PluginDriver(new ViscousDampingPlugin(new ViscousDampingSettings { DampingNsPerMm = 0.1, MaxForceN = 1 }, PluginContext.Standalone("d")));
        for (var k = 0; k < 400; k++)
        {
            damping.Set(("x", 0.1 * k), ("y", -0.1 * k), ("fx_in", 0.25), ("fy_in", -0.5)).Tick(); // +-100 mm/s: -+10 N before the clamp
        }

        Assert.Equal(0.25 - 1.0, damping["fx"], 9);
        Assert.Equal(-0.5 + 1.0, damping["fy"], 9);
    }

    [Fact]
    public void The_lock_spring_is_clamped_on_both_sides_and_adds_to_the_incoming_force()
    {
        var lockPlugin = new PluginDriver(new HapticLockPlugin(new HapticLockSettings { StiffnessNPerMm = 0.5, MaxForceN = 3 }, PluginContext.Standalone("l")));
        lockPlugin.Set(("fx_in", 0.2), ("fy_in", -0.1), ("fz_in", 0.3)).Tick();
        Assert.Equal((0.2, -0.1, 0.3), (lockPlugin["fx"], lockPlugin["fy"], lockPlugin["fz"])); // unlocked: passed through
        Assert.Equal(0.0, lockPlugin["locked"]);

        lockPlugin.Set(("lock", 0.5)).Tick(); // at the threshold: locked at (0, 0, 0)
        lockPlugin.Set(("x", 100), ("y", -100), ("z", 1)).Tick(); // 0.5 N/mm * 100 mm = 50 N, clamped to 3 N
        Assert.Equal(1.0, lockPlugin["locked"]);
        Assert.Equal(0.2 - 3.0, lockPlugin["fx"], 12);
        Assert.Equal(-0.1 + 3.0, lockPlugin["fy"], 12);
        Assert.Equal(0.3 - 0.5, lockPlugin["fz"], 12);
    }

    [Fact]
    public void The_lock_resumes_orientation_without_a_jump_too()
    {
        var lockPlugin = new PluginDriver(new HapticLockPlugin(new HapticLockSettings(), PluginContext.Standalone("l")));
        lockPlugin.Set(("roll", 0.1), ("yaw", -0.2)).Tick();
        lockPlugin.Set(("lock", 1), ("roll", 0.4), ("yaw", 0.3)).Tick(3);
        Assert.Equal((0.1, -0.2), (lockPlugin["roll"], lockPlugin["yaw"]));

        lockPlugin.Set(("lock", 0.4999)).Tick(); // just below the threshold: unlocked, no jump
        Assert.Equal(0.0, lockPlugin["locked"]);
        Assert.Equal(0.1, lockPlugin["roll"], 12);
        Assert.Equal(-0.2, lockPlugin["yaw"], 12);

        lockPlugin.Set(("roll", 0.5), ("yaw", 0.4)).Tick();
        Assert.Equal(0.2, lockPlugin["roll"], 12);
        Assert.Equal(-0.1, lockPlugin["yaw"], 12);
    }

    [Fact]
    public void A_handle_moving_on_the_unlock_tick_does_not_move_the_pose()
    {
        // Locked at x = 10 while the handle drifts to 14; on the unlock tick the handle is at 20: the pose stays at 10
        // (offset -10 taken on that tick), then follows: handle 21 gives 11.
        var lockPlugin = new PluginDriver(new HapticLockPlugin(new HapticLockSettings(), PluginContext.Standalone("l")));
        lockPlugin.Set(("x", 10)).Tick();
        lockPlugin.Set(("lock", 1)).Tick();
        lockPlugin.Set(("x", 14)).Tick(3);

        lockPlugin.Set(("lock", 0), ("x", 20)).Tick();
        Assert.Equal(10.0, lockPlugin["x"], 12);

        lockPlugin.Set(("x", 21)).Tick();
        Assert.Equal(11.0, lockPlugin["x"], 12);
    }

    [Fact]
    public void Walls_clamp_the_negative_side_and_invert_x_and_z_on_request()
    {
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { MaxForceN = 1.5, InvertForceX = true, InvertForceZ = true }, PluginContext.Standalone("w")));

        walls.Set(("fx", 0.5), ("fy", -5), ("fz", -0.25)).Tick();

        Assert.Equal((-0.5, -1.5, 0.25), (walls["fx"], walls["fy"], walls["fz"]));
    }

    [Fact]
    public void Mirrored_walls_reflect_the_y_force_only()
    {
        // Left arm: the robot frame is the device frame mirrored in x-z, so a robot force (fx, fy, fz) is (fx, -fy, fz)
        // at the device (gain 1, ratio 1).
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { Mirror = true, MaxForceN = 10 }, PluginContext.Standalone("w")));

        walls.Set(("fx", 0.5), ("fy", 0.75), ("fz", -0.25)).Tick();

        Assert.Equal((0.5, -0.75, -0.25), (walls["fx"], walls["fy"], walls["fz"]));
    }
}
