using RobotControl.Hardware.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// A host stall on the virtual robot (the teleop graph, the stall at 1 s), graded by its length: shorter than the stall
/// limit nothing; up to the modules' torque-off stage a soft trip (the arms hold at the goals last sent, PEDAL_UP) and
/// the harness, as a surgeon, re-engages 200 ms later without a step; past the stage E_STOP (see
/// <see cref="SafetyFaultTests"/>). The frames on the wire are asserted.
/// </summary>
public sealed class HostStallTests
{
    private const double FaultAtS = 1.0;

    [Fact]
    public void A_stall_shorter_than_the_stall_limit_is_nothing()
    {
        var run = SafetyRun.Of("stall=5ms@1s", 1.3);
        Assert.Empty(run.Safety.Trips);
        Assert.Equal(RunLevel.PedalDown, run.FinalLevel);
        Assert.Equal([RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown], run.Safety.RunLevels.Select(l => l.To));
    }

    [Fact]
    public void A_20_ms_stall_is_a_soft_trip_the_arms_hold_where_they_were_sent_and_re_engaging_starts_there()
    {
        var run = SafetyRun.Of("stall=20ms@1s", 1.6);
        var trip = Assert.Single(run.Safety.Trips);
        Assert.Equal(SafetyCheck.HostStall, trip.Check);
        Assert.True(trip.Soft);
        Assert.Equal(SafeState.Hold, trip.Action);
        Assert.InRange(trip.Measured, 20, 25); // the stall and the cycle it fell in
        Assert.Equal(10, trip.Limit);
        Assert.InRange(trip.TimeSeconds - FaultAtS, 0.020, 0.025);

        // PEDAL_DOWN -> PEDAL_UP at the trip, the harness presses again 200 ms later, teleoperation goes on.
        var levels = run.Safety.RunLevels;
        Assert.Equal([RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown, RunLevel.PedalUp, RunLevel.PedalDown], levels.Select(l => l.To));
        var up = levels[3];
        var again = levels[4];
        Assert.Equal(("supervisor", trip.TimeSeconds), (up.Source, up.TimeSeconds));
        Assert.Matches(@"^host_stall: 2\d\.\d ms \(limit 10 ms\): hold, back to PEDAL_UP$", up.Reason);
        Assert.Equal("harness", again.Source);
        Assert.InRange(again.TimeSeconds - up.TimeSeconds, 0.200, 0.205);
        Assert.Equal(1, run.Safety.ReEngagements);
        Assert.Equal(RunLevel.PedalDown, run.FinalLevel);
        Assert.All(run.Motors, m => Assert.True(m.DriverEnabled, $"{m.Name} not driven"));

        // The hold: every goal frame between the trip's write and the press carries the same goals.
        Assert.True(run.GoalsFrozenBetween(trip.TimeSeconds + 0.001, again.TimeSeconds), "goals moved while holding");
        // Re-engaging: no goal over the cap, and the first goals stay within a few counts of the held ones.
        Assert.InRange(run.WorstStepOverCap(), 0, 1);
        Assert.Equal(0, run.Safety.StepCapHits);
        var held = run.FramesBetween(trip.TimeSeconds + 0.001, again.TimeSeconds)[^1];
        foreach (var frame in run.FramesBetween(again.TimeSeconds, again.TimeSeconds + 0.005))
        {
            Assert.All(run.Motors, m => Assert.InRange(Math.Abs(frame.Goals[m.ModuleId][m.Channel] - held.Goals[m.ModuleId][m.Channel]), 0, 5));
        }
    }

    [Fact]
    public void Without_the_harness_pressing_again_a_soft_trip_leaves_the_arms_holding_at_pedal_up()
    {
        var run = SafetyRun.Of("stall=20ms@1s", 1.6, reEngageAfter: null);
        Assert.True(Assert.Single(run.Safety.Trips).Soft);
        Assert.Equal(RunLevel.PedalUp, run.FinalLevel);
        Assert.Equal(0, run.Safety.ReEngagements);
        Assert.True(run.GoalsFrozenFrom(run.Safety.Trips[0].TimeSeconds + 0.001), "goals moved while holding");
        Assert.InRange(run.Safety.PedalDownSeconds, 1.01, 1.03);
    }
}
