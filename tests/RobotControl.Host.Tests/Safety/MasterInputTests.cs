using RobotControl.Definitions.Model;
using RobotControl.Host.Harness;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>The master (input device) checks on the virtual robot: stale input (the master timeout) and an input jump (teleop graph, fault at 1 s).</summary>
public sealed class MasterInputTests
{
    private const double FaultAtS = 1.0;

    [Fact]
    public void Stale_input_forces_pedal_up_within_the_master_timeout_and_the_arms_hold()
    {
        var run = SafetyRun.Of("stale=touch_right@1s", 1.5);
        var trip = run.Trip(SafetyCheck.MasterTimeout);
        Assert.Equal("right", trip.Joint);
        Assert.Equal(SafeState.Hold, trip.Action);
        Assert.Equal(50, trip.Limit);
        Assert.InRange(trip.Measured, 50, 53);
        // The reading's age passes 50 ms at 1.050 s; the next bus cycle sees it (51.5 ms measured).
        Assert.InRange(trip.TimeSeconds - FaultAtS, 0.050, 0.054);
        Assert.Single(run.Safety.Trips);
        Assert.Equal(RunLevel.PedalUp, run.FinalLevel);
        Assert.Equal(RunLevel.PedalUp, run.Safety.FinalRunLevel);
        var last = run.Safety.RunLevels[^1];
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "supervisor"), (last.From, last.To, last.Source));
        Assert.StartsWith("master_timeout right: 5", last.Reason, StringComparison.Ordinal);
        Assert.EndsWith(" ms (limit 50 ms): hold, back to PEDAL_UP", last.Reason, StringComparison.Ordinal);
        Assert.True(trip.Soft);
        Assert.Equal(0, run.Safety.ReEngagements); // the harness pressed again every 200 ms; the stale data refused each press
        Assert.InRange(last.TimeSeconds - trip.TimeSeconds, 0, 0.001);
        Assert.All(run.Motors, m => Assert.True(m.DriverEnabled, $"{m.Name} not driven"));
        Assert.True(run.GoalsFrozenFrom(trip.TimeSeconds + 0.1), "goals moved after the hold settled");
        Assert.All(run.Motors, m => Assert.InRange(Math.Abs(m.OutputRad - m.GoalRad), 0, 0.05));
        Assert.InRange(run.WorstStepOverCap(), 0, 1);
        Assert.True(run.LastForceS <= trip.TimeSeconds + 0.002, $"haptic force rendered at {run.LastForceS} s, after the timeout");
        var json = run.Report.ToJson();
        Assert.Contains("\"final_run_level\": \"PEDAL_UP\"", json, StringComparison.Ordinal);
        Assert.Contains("\"check\": \"master_timeout\"", json, StringComparison.Ordinal);
    }

    [Fact]
    public void With_torque_off_as_its_safe_state_the_master_timeout_is_an_e_stop()
    {
        var run = SafetyRun.WithSafetySection("{ \"master_timeout_ms\": 20, \"safe_state\": { \"master_timeout\": \"torque_off\" } }", "stale=touch_left@1s", 1.3);
        var trip = run.Trip(SafetyCheck.MasterTimeout);
        Assert.Equal("left", trip.Joint);
        Assert.Equal(20, trip.Limit);
        Assert.InRange(trip.TimeSeconds - FaultAtS, 0.020, 0.024);
        Assert.Equal(SafeState.TorqueOff, trip.Action);
        Assert.Equal(RunLevel.EStop, run.FinalLevel);
        Assert.All(run.Motors, m => Assert.False(m.DriverEnabled, $"{m.Name} still driven"));
    }

    [Fact]
    public void A_master_jump_is_a_soft_trip_within_2_ms_no_goal_moves_toward_it_and_re_engaging_does_not_step()
    {
        // A 50 mm jump of the right master in one 1 ms sample implies 50 m/s at the device (limit 2 m/s). The Touch
        // keeps its last plausible reading, the robot node publishes nothing that tick, the supervisor trips.
        var run = SafetyRun.Of("jump=touch_right:50mm@1s", 1.5);
        var trip = Assert.Single(run.Safety.Trips);
        Assert.Equal((SafetyCheck.MasterJump, "right", "mm/s", 2000.0), (trip.Check, trip.Joint, trip.Unit, trip.Limit));
        Assert.InRange(trip.Measured, 49_000, 51_000);
        Assert.True(trip.Soft);
        Assert.InRange(trip.TimeSeconds - FaultAtS, 0, 0.002);
        var levels = run.Safety.RunLevels;
        Assert.Equal([RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown, RunLevel.PedalUp, RunLevel.PedalDown], levels.Select(l => l.To));
        Assert.Equal("supervisor", levels[3].Source);
        Assert.Equal("harness", levels[4].Source);

        // Without the check the jump asked the joints for up to 0.41 rad in one write and the step cap spread it over
        // 182 capped goals (measured before it existed); now no goal ever wanted to move further than the cap: none
        // toward the jumped pose, none at re-engagement.
        Assert.Equal(0, run.Safety.StepCapHits);
        Assert.InRange(run.WorstStepOverCap(), 0, 1);
        Assert.True(run.GoalsFrozenBetween(trip.TimeSeconds + 0.001, levels[4].TimeSeconds), "goals moved while holding");
        Assert.Equal(RunLevel.PedalDown, run.FinalLevel);
        Assert.Equal(1500, run.Report.Ticks);
    }

    [Fact]
    public void With_torque_off_as_its_safe_state_a_master_jump_is_an_e_stop()
    {
        var run = SafetyRun.WithSafetySection("""{ "safe_state": { "master_jump": "torque_off" } }""", "jump=touch_right:50mm@1s", 1.2);
        var trip = run.Trip(SafetyCheck.MasterJump);
        Assert.False(trip.Soft);
        Assert.Equal(SafeState.TorqueOff, trip.Action);
        Assert.Equal(RunLevel.EStop, run.FinalLevel);
        Assert.All(run.Motors, m => Assert.False(m.DriverEnabled, $"{m.Name} still driven"));
    }

    [Fact]
    public void The_jump_and_stale_faults_parse_and_name_what_is_wrong()
    {
        var f = FaultInjection.Parse("jump=touch_right:50mm@5s,stale=touch_left@2s").TimedFaults;
        Assert.Equal((TimedFaultKind.Jump, "touch_right", 50.0, 5.0), (f[0].Kind, f[0].Target, f[0].JumpMm, f[0].At.TotalSeconds));
        Assert.Equal((TimedFaultKind.Stale, "touch_left", 2.0), (f[1].Kind, f[1].Target, f[1].At.TotalSeconds));
        Assert.Equal("jump=touch_right:50mm@5s,stale=touch_left@2s", FaultInjection.Parse("jump=touch_right:50mm@5s,stale=touch_left@2s").ToString());
        var e = Assert.Throws<FormatException>(() => FaultInjection.Parse("jump=touch_right:50@5s"));
        Assert.Equal("--inject 'jump=touch_right:50@5s': expected jump=<touch>:<distance>mm@<time> with a distance from -1000 to 1000 mm other than 0, e.g. jump=touch_right:50mm@5s", e.Message);
        var unknown = Assert.Throws<FormatException>(() => SafetyRun.Of("stale=touch_middle@1s", 0.1));
        Assert.Equal("--inject 'stale=touch_middle@1s': no plug-in 'touch_middle' in the graph (plug-ins that take stale faults: touch_right, touch_left)", unknown.Message);
        var unable = Assert.Throws<FormatException>(() => SafetyRun.Of("jump=ik_right:50mm@1s", 0.1));
        Assert.Equal("--inject 'jump=ik_right:50mm@1s': plug-in 'ik_right' cannot take jump faults (plug-ins that take them: touch_right, touch_left)", unable.Message);
    }
}
