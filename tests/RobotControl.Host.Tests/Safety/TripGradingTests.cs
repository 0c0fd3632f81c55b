using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// How a trip is graded on a supervised virtual LB: a silence shorter than the modules' torque-off stage (their second
/// watchdog stage, 500 ms) with a safe state of hold is a soft trip (PEDAL_UP); from the stage on, or with torque off
/// as its safe state, it is E_STOP; each check is recorded once per episode of teleoperation (soft) or until a reset.
/// </summary>
public sealed class TripGradingTests
{
    [Theory]
    [InlineData(20)]
    [InlineData(499.9)]
    public void A_host_stall_shorter_than_the_torque_off_stage_is_a_soft_trip_measured_to_the_write_after_it(double stallMs)
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Stall(TimeSpan.FromMilliseconds(stallMs));
        lb.Cycles(1);

        var trip = lb.Supervisor.Trips[0];
        Assert.Equal((SafetyCheck.HostStall, string.Empty, stallMs, 10.0, "ms", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        var back = lb.Supervisor.History[3]; // after homing, PEDAL_UP and PEDAL_DOWN (the modules' own torque-off may follow)
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "supervisor", FormattableString.Invariant($"host_stall: {stallMs} ms (limit 10 ms): hold, back to PEDAL_UP")), (back.From, back.To, back.Source, back.Reason));
    }

    [Fact]
    public void A_host_stall_of_exactly_the_stall_limit_is_nothing()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Stall(10 * SupervisedLb.LoopPeriod);
        lb.Cycles(5);

        Assert.Empty(lb.Supervisor.Trips);
        Assert.Equal(RunLevel.PedalDown, lb.Supervisor.Level);
    }

    [Fact]
    public void A_host_stall_of_exactly_the_torque_off_stage_is_an_e_stop_with_the_motors_off()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Stall(TimeSpan.FromMilliseconds(500));
        lb.Cycles(1);

        var trip = lb.Supervisor.Trips[0];
        Assert.Equal((SafetyCheck.HostStall, 500.0, 500.0, SafeState.TorqueOff, false), (trip.Check, trip.Measured, trip.Limit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.PedalDown, RunLevel.EStop, "supervisor", "host_stall: torque_off"), lb.LastMove);
        Assert.True(lb.Supervisor.MotorsTrippedOff);
        var off = lb.Robot.StateHistory.Single(h => h.Source == "emergency hold");
        Assert.Equal((RobotState.Enabled, "host_stall: torque_off"), (off.From, off.Reason));

        // The modules' own torque-off, read back, is a module fault: recorded, and the level stays E_STOP.
        lb.Cycles(20);
        var fault = Assert.Single(lb.Supervisor.Trips, t => t.Check == SafetyCheck.ModuleFault);
        Assert.Equal((string.Empty, (double)RobotFaults.WatchdogTripped, 0.0, "fault flags", SafeState.TorqueOff, false), (fault.Joint, fault.Measured, fault.Limit, fault.Unit, fault.Action, fault.Soft));
        Assert.Single(lb.Supervisor.History, h => h.To == RunLevel.EStop);
        Assert.Single(lb.Robot.StateHistory, h => h.Source == "emergency hold"); // the motors went off once
    }

    [Fact]
    public void With_torque_off_as_its_safe_state_a_short_host_stall_is_an_e_stop()
    {
        using var lb = SupervisedLb.AtPedalDown(SupervisedLb.WithSafeState(SafetyCheck.HostStall, SafeState.TorqueOff));
        lb.Stall(TimeSpan.FromMilliseconds(20));
        lb.Cycles(2);

        var trip = Assert.Single(lb.Supervisor.Trips);
        Assert.Equal((20.0, 10.0, SafeState.TorqueOff, false), (trip.Measured, trip.Limit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.EStop, "host_stall: torque_off"), (lb.Supervisor.Level, lb.LastMove.Reason));
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);
    }

    [Fact]
    public void At_e_stop_and_at_init_the_host_is_not_timed()
    {
        using var lb = new SupervisedLb();
        lb.StopNow();

        lb.Cycles(3);
        lb.Stall(TimeSpan.FromMilliseconds(100));
        lb.Cycles(3);
        Assert.Single(lb.Supervisor.Trips); // the operator's: no host stall at E_STOP

        lb.Supervisor.Reset("console");
        lb.Cycles(3);
        lb.Stall(TimeSpan.FromMilliseconds(100));
        lb.Cycles(3);
        Assert.Single(lb.Supervisor.Trips);
        Assert.False(lb.Supervisor.TeleopAllowed);
    }

    [Fact]
    public void A_loop_that_stops_ticking_at_pedal_down_is_a_soft_deadline_miss()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.CyclesUntil(() => lb.Supervisor.Trips.Count > 0, TimeSpan.FromMilliseconds(30), ticking: false);

        var trip = Assert.Single(lb.Supervisor.Trips);
        Assert.Equal((SafetyCheck.DeadlineMiss, "loop", 10.0, "ms", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.InRange(trip.Measured, 10.001, 13); // timed before each write: the first write after 10 ms
        Assert.Equal(RunLevel.PedalUp, lb.Supervisor.Level);
    }

    [Fact]
    public void With_torque_off_as_its_safe_state_a_silent_module_is_an_e_stop_at_its_limit()
    {
        using var lb = new SupervisedLb(SupervisedLb.WithSafeState(SafetyCheck.ModuleSilent, SafeState.TorqueOff));
        lb.Supervisor.PedalDown("console");
        lb.Sim.ScheduleTransmitBreak(12, lb.Sim.Elapsed);
        lb.CyclesUntil(() => lb.Supervisor.Level == RunLevel.EStop, TimeSpan.FromMilliseconds(40));

        var trip = Assert.Single(lb.Supervisor.Trips, t => t.Check == SafetyCheck.ModuleSilent);
        Assert.Equal(("left.upper_arm", 10.0, "ms", SafeState.TorqueOff, false), (trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.InRange(trip.Measured, 10.001, 14);
    }

    [Fact]
    public void A_silent_module_trips_when_its_silence_exceeds_module_silent_ms()
    {
        // 30 ms: longer than one cycle with the silent module's timeouts (about 11 ms), so the limit decides.
        using var lb = new SupervisedLb(SupervisedLb.FileLimits with { ModuleSilentMs = 30 });
        lb.Sim.ScheduleTransmitBreak(12, lb.Sim.Elapsed);
        lb.CyclesUntil(() => lb.Supervisor.Trips.Any(t => t.Check == SafetyCheck.ModuleSilent), TimeSpan.FromMilliseconds(80));

        var trip = lb.Supervisor.Trips.Single(t => t.Check == SafetyCheck.ModuleSilent);
        Assert.Equal(("left.upper_arm", 30.0, "ms", SafeState.Hold, true), (trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.InRange(trip.Measured, 30.001, 45); // the first check after 30 ms of silence (a cycle lasts about 11 ms)
    }

    [Fact]
    public void Modules_holding_on_their_own_at_pedal_down_are_a_soft_module_fault_and_the_next_pedal_down_releases_them()
    {
        // A stall limit of 100 ms: a 50 ms stall is no host stall, but the modules hold from 30 ms on (their first stage).
        using var lb = SupervisedLb.AtPedalDown(SupervisedLb.FileLimits with { DeadlineMissesInARow = 100 });
        lb.Stall(TimeSpan.FromMilliseconds(50));
        lb.CyclesUntil(() => lb.Supervisor.Trips.Count > 0, TimeSpan.FromMilliseconds(50)); // the status poll reads the holds

        var trip = Assert.Single(lb.Supervisor.Trips);
        Assert.Equal((SafetyCheck.ModuleFault, string.Empty, 6.0, 0.0, "modules holding", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "supervisor", "module_fault: 6 modules holding (limit 0 modules holding): hold, back to PEDAL_UP"), lb.LastMove);

        lb.Supervisor.PedalDown("console"); // acknowledges the modules' holds at the next write
        lb.Cycles(20);
        Assert.Equal(0, lb.Robot.ModulesHolding);
        Assert.Equal(RunLevel.PedalDown, lb.Supervisor.Level);
        Assert.Single(lb.Supervisor.Trips);
    }

    [Fact]
    public void A_setpoint_the_robot_refuses_is_a_non_finite_e_stop_that_holds()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Robot.WriteJointSetpoints(0, [.. lb.Robot.Definition.Joints.Select(_ => double.NaN)]);
        lb.Cycles(2);

        var trip = Assert.Single(lb.Supervisor.Trips);
        Assert.Equal((SafetyCheck.NonFinite, "setpoint", 0.0, "rad", SafeState.Hold, false), (trip.Check, trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.True(double.IsNaN(trip.Measured));
        Assert.Equal((RunLevel.PedalDown, RunLevel.EStop, "supervisor", "non_finite setpoint: hold"), lb.LastMove);
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.False(lb.Supervisor.MotorsTrippedOff);
    }

    [Fact]
    public void A_soft_trip_is_recorded_once_per_episode_of_teleoperation_and_again_after_a_reset()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;
        SoftStall(lb);
        SoftStall(lb); // at PEDAL_UP, the same episode: not recorded again
        Assert.Single(supervisor.Trips);

        supervisor.PedalDown("console"); // a new episode
        SoftStall(lb);
        Assert.Equal(2, supervisor.Trips.Count);

        lb.StopNow();

        supervisor.Reset("console");
        supervisor.Home("console");
        SoftStall(lb); // at PEDAL_UP, no pedal down since: the reset started anew
        Assert.Equal([true, true, false, true], supervisor.Trips.Select(t => t.Soft));
        Assert.All(supervisor.Trips.Where(t => t.Soft), t => Assert.Equal(SafetyCheck.HostStall, t.Check));
    }

    private static void SoftStall(SupervisedLb lb)
    {
        lb.Stall(TimeSpan.FromMilliseconds(20));
        lb.Cycles(3);
    }
}
