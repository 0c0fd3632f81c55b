using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Robot.States;

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

    [Theory]
    [InlineData(20)]  // the modules follow their last goals meanwhile
    [InlineData(50)]  // the modules hold from 30 ms on (their first watchdog stage), acknowledged at the pedal down
    [InlineData(200)]
    public void A_stall_short_of_the_modules_torque_off_stage_is_a_soft_trip_the_arms_hold_where_they_were_sent_and_re_engaging_starts_there(int stallMs)
    {
        var run = SafetyRun.Of($"stall={stallMs}ms@1s", 1.4 + (stallMs / 1000.0));
        var trip = Assert.Single(run.Safety.Trips);
        Assert.Equal(SafetyCheck.HostStall, trip.Check);
        Assert.True(trip.Soft);
        Assert.Equal(SafeState.Hold, trip.Action);
        Assert.InRange(trip.Measured, stallMs, stallMs + 5); // the stall and the cycle it fell in
        Assert.Equal(10, trip.Limit);
        Assert.InRange(trip.TimeSeconds - FaultAtS, stallMs / 1000.0, (stallMs + 5) / 1000.0);
        Assert.Equal(stallMs >= 30 ? 6 : 0, run.Report.Faults.Count(f => f.Message.Contains("holding its motors", StringComparison.Ordinal)));

        // PEDAL_DOWN -> PEDAL_UP at the trip, the harness presses again 200 ms later, teleoperation goes on.
        var levels = run.Safety.RunLevels;
        Assert.Equal([RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown, RunLevel.PedalUp, RunLevel.PedalDown], levels.Select(l => l.To));
        var up = levels[3];
        var again = levels[4];
        Assert.Equal(("supervisor", trip.TimeSeconds), (up.Source, up.TimeSeconds));
        Assert.Matches(@"^host_stall: \d+(\.\d+)? ms \(limit 10 ms\): hold, back to PEDAL_UP$", up.Reason);
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

    [Fact]
    public void Homing_after_the_motors_went_off_during_the_modules_hold_acknowledges_the_hold_and_turns_them_on()
    {
        // A 200 ms stall: the modules hold from 30 ms on (bus_hold, refusing goals and torque-on until acknowledged);
        // nobody presses the pedal again, the operator turns the motors off (INIT) and homes.
        IReadOnlyList<Robot.Bus.HomingResult>? homed = null;
        var run = SafetyRun.Of("stall=200ms@1s", 1.4, reEngageAfter: null, afterRun: supervisor =>
        {
            supervisor.MotorsOff("operator");
            Assert.Equal(RunLevel.Init, supervisor.Level);
            homed = supervisor.Home("operator");
        });

        Assert.Equal(6, run.Report.Faults.Count(f => f.Message.Contains("holding its motors", StringComparison.Ordinal)));
        Assert.NotNull(homed);
        Assert.Equal(RunLevel.PedalUp, run.FinalLevel);
        Assert.All(run.Motors, m => Assert.True(m.DriverEnabled, $"{m.Name} not driven after homing"));
    }

    [Fact]
    public void Homing_that_a_silent_module_cannot_finish_goes_back_to_init_and_names_its_motors()
    {
        // A module silent from 1 s: E_STOP at the modules' torque-off stage; the operator resets and homes, with the
        // module still silent.
        Exception? refused = null;
        var run = SafetyRun.Of("silent=right.forearm@1s", 1.7, afterRun: supervisor =>
        {
            supervisor.Reset("operator");
            refused = Record.Exception(() => supervisor.Home("operator"));
        });

        Assert.NotNull(refused);
        Assert.Matches(@"^homing incomplete: 2 of 12 motors not homed \(first: right\.tool_roll NoReply: ", refused.Message); // the silent module's motors
        Assert.Equal(RunLevel.Init, run.FinalLevel); // not left at HOMING
        Assert.All(run.Motors, m => Assert.False(m.DriverEnabled, $"{m.Name} driven after a failed homing"));
    }

    /// <summary>Cycles the bus of <paramref name="session"/> with no tick (a loop that stopped ticking) for <paramref name="ms"/> or until E_STOP.</summary>
    private static void CycleWithoutTicks(RobotSession session, double ms)
    {
        var bus = session.Robot;
        var clock = session.Connection.VirtualClock!;
        var start = clock.GetTimestamp();
        using (bus.OwnBus())
        {
            while (clock.GetElapsedTime(start) < TimeSpan.FromMilliseconds(ms) && session.Supervisor.Level != RunLevel.EStop)
            {
                bus.Write();
                bus.Read();
                bus.Publish();
                bus.Check();
            }

            bus.Write();
        }
    }

    [Fact]
    public void A_loop_that_stops_ticking_while_it_drives_is_a_soft_deadline_miss_the_arms_hold_and_the_pedal_is_refused_until_it_ticks()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        supervisor.PedalDown("pedal");
        session.RunVirtual(100);

        CycleWithoutTicks(session, 100); // shorter than the modules' torque-off stage (500 ms)

        var soft = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.DeadlineMiss, "loop", true, SafeState.Hold), (soft.Check, soft.Joint, soft.Soft, soft.Action)); // between ticks: no plug-in to name
        Assert.InRange(soft.Measured, 10, 14);
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp), (supervisor.History[^1].From, supervisor.History[^1].To));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        var refused = Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("pedal"));
        Assert.Matches(@"^pedal down \(pedal\) refused: the control loop has not ticked for \d+ ms$", refused.Message);
        session.RunVirtual(200);
        supervisor.PedalDown("pedal");
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
    }

    [Fact]
    public void A_loop_dead_for_the_modules_torque_off_stage_takes_the_motors_off_also_at_pedal_up()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        session.RunVirtual(100);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level); // never pressed: the arms hold, the loop is watched all the same

        CycleWithoutTicks(session, 700);

        Assert.Equal(RunLevel.EStop, supervisor.Level);
        var trip = supervisor.Trips[^1];
        Assert.Equal((SafetyCheck.DeadlineMiss, false, SafeState.TorqueOff), (trip.Check, trip.Soft, trip.Action));
        Assert.InRange(trip.Measured, 500, 505); // the modules' torque-off stage: the bus no longer stands in for a dead loop
        Assert.True(supervisor.MotorsTrippedOff);
        Assert.NotEqual(RobotState.Enabled, session.Robot.State);
    }

    [Fact]
    public void After_an_e_stop_from_a_stall_past_the_torque_off_stage_a_reset_needs_no_re_homing_when_the_pots_confirm_every_position()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        supervisor.PedalDown("pedal");
        session.RunVirtual(300);
        session.Simulation!.Advance(TimeSpan.FromMilliseconds(600)); // the host stops; the modules hold at 30 ms and switch off at 500
        session.RunVirtual(400);
        var stall = supervisor.Trips.First(t => t.Check == SafetyCheck.HostStall);
        Assert.Equal((false, SafeState.TorqueOff), (stall.Soft, stall.Action));
        Assert.Equal(RunLevel.EStop, supervisor.Level);

        supervisor.Reset("operator");
        var homed = supervisor.Home("operator");

        Assert.Empty(homed); // not re-homed: the pots confirmed every motor
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        Assert.StartsWith("after an E-STOP from a stall, the pots confirm every position", supervisor.History[^1].Reason, StringComparison.Ordinal);
    }
}
