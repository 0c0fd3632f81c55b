using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.Robot.States;
using RobotControl.TestSupport;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// The operator's commands on a supervised virtual LB: homing, pedal down and up, motors off, reset and the emergency
/// stop; the run levels they move through with their reasons, and the exact refusals the console shows.
/// </summary>
public sealed class OperatorCommandTests
{
    [Fact]
    public void Homing_with_no_position_in_doubt_turns_the_motors_on_without_re_homing_and_holds_at_pedal_up()
    {
        using var lb = new SupervisedLb(home: false);
        var supervisor = lb.Supervisor;
        Assert.Equal((RunLevel.Init, RobotState.Discovered), (supervisor.Level, lb.Robot.State));
        Assert.True(lb.Robot.IsHolding); // from the supervisor's creation on

        Assert.Empty(supervisor.Home("console"));

        Assert.Equal(
            [
                (RunLevel.Init, RunLevel.Homing, "console", "homing from the joint pots"),
                (RunLevel.Homing, RunLevel.PedalUp, "console", "no module reports a lost position or a pot mismatch: not re-homed; motors on, holding"),
            ],
            supervisor.History.Select(h => (h.From, h.To, h.Source, h.Reason)));
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.DoesNotContain(lb.Robot.StateHistory, h => h.To == RobotState.Homing);

        // At PEDAL_UP the goals stay where the motors were, whatever the setpoints say.
        var held = lb.Robot.Motors.Select(m => m.PositionRad).ToArray();
        lb.Robot.WriteJointSetpoints(0, [.. lb.Robot.Definition.Joints.Select(j => j.MidRad + (0.3 * (j.MaxRad - j.MidRad)))]);
        lb.Cycles(50);
        Assert.Equal(held, lb.Robot.Motors.Select(m => lb.Robot.SentGoalRad(m)));
        Assert.Empty(supervisor.Trips);
    }

    [Fact]
    public void A_joint_turned_while_its_module_was_off_is_re_homed_and_pedal_up_holds_it_where_it_is_now()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.PedalDown("console");
        lb.Cycles(20);
        supervisor.MotorsOff("console");
        lb.Cycles(20);

        // The upper arm's module loses power while the elbow is turned by hand: it comes back with the position it
        // saved, its pot disagrees, and the robot sees the reset as a fault.
        var (elbow, axis) = lb.Motor("right.elbow");
        lb.Sim.TurnWhileOff(axis, axis.OutputAngleRad + 0.5);
        lb.Sim.Advance(TimeSpan.FromMilliseconds(2));
        lb.Cycles(5);
        Assert.Equal(RobotState.Fault, lb.Robot.State);

        var homed = supervisor.Home("console");

        Assert.Equal(12, homed.Count);
        Assert.All(homed, r => Assert.True(r.Succeeded, r.ToString()));
        Assert.Equal((RunLevel.PedalUp, "12 motors homed and verified (1 had lost their position); motors on, holding"), (supervisor.Level, supervisor.History[^1].Reason));
        var at = elbow.PositionRad;
        Assert.InRange(at - axis.OutputAngleRad, -0.01, 0.01);

        // Held where the elbow is now, not where it was before it turned: no motion back, no tracking error; from the
        // first write on (the step cap starts at the re-homed position, not at the goal sent before homing).
        for (var cycle = 0; cycle < 50; cycle++)
        {
            lb.Cycles(1);
            Assert.InRange(lb.Robot.SentGoalRad(elbow) - at, -0.01, 0.01);
        }

        lb.CyclesFor(TimeSpan.FromMilliseconds(600));
        Assert.Equal(at, lb.Robot.SentGoalRad(elbow));
        Assert.InRange(elbow.PositionRad - at, -0.01, 0.01);
        Assert.Empty(supervisor.Trips);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
    }

    [Fact]
    public void After_a_reset_every_motor_is_homed_again_and_the_motors_go_on_holding()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        lb.StopNow();
        supervisor.Reset("console");
        Assert.Equal((RunLevel.EStop, RunLevel.Init, "console", "operator reset: motors off, faults cleared; homing needed before motion"), lb.LastMove);
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);

        var homed = supervisor.Home("console");

        Assert.Equal(12, homed.Count);
        Assert.Equal((RunLevel.Homing, RunLevel.PedalUp, "console", "12 motors homed and verified (after a reset); motors on, holding"), lb.LastMove);
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.Contains(lb.Robot.StateHistory, h => h.To == RobotState.Homing);
        Assert.True(lb.Robot.IsHolding);

        // Homed since the reset: turning the motors off and on again needs no re-homing.
        supervisor.MotorsOff("console");
        Assert.Empty(supervisor.Home("console"));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
    }

    [Fact]
    public void An_emergency_stop_and_a_reset_between_two_cycles_leave_init()
    {
        using var lb = new SupervisedLb();
        using (lb.Robot.OwnBus())
        {
            lb.Supervisor.EmergencyStop("console", "stop");
            lb.Supervisor.Reset("console");
        }

        lb.Cycles(5);
        Assert.Equal(RunLevel.Init, lb.Supervisor.Level);
        Assert.Single(lb.Supervisor.Trips);
    }

    [Fact]
    public void Homing_that_fails_for_a_motor_returns_to_init_and_says_which_motor_failed_first()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        lb.StopNow();
        supervisor.Reset("console");
        lb.Sim.ScheduleTransmitBreak(3, lb.Sim.Elapsed); // the right forearm's module (2 motors) stops answering

        var error = Assert.Throws<InvalidOperationException>(() => supervisor.Home("console"));

        Assert.Equal("homing incomplete: 2 of 12 motors not homed (first: right.tool_roll NoReply: reading the module's pot calibration failed); the run level stays INIT", error.Message);
        Assert.Equal((RunLevel.Homing, RunLevel.Init, "console", "homing incomplete: 2 of 12 motors not homed"), lb.LastMove);
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);
    }

    [Fact]
    public void At_e_stop_homing_is_refused_naming_the_trip_that_caused_it()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;

        // A soft trip first (stale master data: back to PEDAL_UP), then the over-current that makes it E_STOP.
        supervisor.ReportInputAge(1, 80);
        lb.Cycles(1);
        Assert.True(Assert.Single(supervisor.Trips).Soft);
        supervisor.ReportInputAge(1, 0);
        var (elbow, axis) = lb.Motor("right.elbow");
        axis.CurrentSenseOffsetA = 2.5 * elbow.CurrentLimitA;
        lb.CyclesUntil(() => supervisor.Level == RunLevel.EStop, TimeSpan.FromMilliseconds(200));
        var trip = supervisor.Trips[^1];
        Assert.Equal(SafetyCheck.OverCurrent, trip.Check);

        var error = Assert.Throws<InvalidOperationException>(() => supervisor.Home("console"));

        Assert.Equal(FormattableString.Invariant($"homing (console) refused: E_STOP since the over_current trip right.elbow ({trip.Measured:0.###} A, limit 0.076); an operator reset comes first"), error.Message);
        Assert.Equal(RunLevel.EStop, supervisor.Level);

        // After a reset and homing, the next E_STOP is named, not the one before the reset.
        axis.CurrentSenseOffsetA = 0;
        supervisor.Reset("console");
        supervisor.Home("console");
        lb.Cycles(5);
        lb.StopNow();
        error = Assert.Throws<InvalidOperationException>(() => supervisor.Home("console"));
        Assert.Equal("homing (console) refused: E_STOP by an operator's emergency stop; an operator reset comes first", error.Message);
    }

    [Fact]
    public void Pedal_down_and_reset_outside_their_levels_are_refused_with_the_level_named()
    {
        using var lb = new SupervisedLb(home: false);
        var supervisor = lb.Supervisor;

        Assert.Equal("pedal down (console) needs the run level PEDAL_UP, it is INIT", Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console")).Message);
        Assert.Equal("reset (console) applies at E_STOP only, the run level is INIT", Assert.Throws<InvalidOperationException>(() => supervisor.Reset("console")).Message);
        supervisor.Home("console");
        Assert.Equal("reset (console) applies at E_STOP only, the run level is PEDAL_UP", Assert.Throws<InvalidOperationException>(() => supervisor.Reset("console")).Message);
        lb.StopNow();
        Assert.Equal("pedal down (console) needs the run level PEDAL_UP, it is E_STOP", Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console")).Message);
        Assert.Equal(RunLevel.EStop, supervisor.Level);
    }

    [Fact]
    public void Pedal_down_is_refused_while_an_arm_s_input_data_is_older_than_the_master_timeout_and_allowed_at_exactly_the_timeout()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.ReportInputAge(1, 61.25);
        Assert.Equal(
            "pedal down (console) refused: the input data of the left arm is 61.3 ms old (master_timeout_ms 50)",
            Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console")).Message);

        supervisor.ReportInputAge(1, double.NaN); // no age known: too old
        Assert.Equal(double.PositiveInfinity, supervisor.Inputs.AgeMs(1));
        Assert.Equal(
            "pedal down (console) refused: the input data of the left arm is Infinity ms old (master_timeout_ms 50)",
            Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console")).Message);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        supervisor.ReportInputAge(1, 50);
        supervisor.PedalDown("console");
        Assert.Equal((RunLevel.PedalUp, RunLevel.PedalDown, "console", "pedal down: teleoperation drives the arms"), lb.LastMove);
        lb.Cycles(20);
        Assert.Empty(supervisor.Trips); // 50 ms old is not older than the timeout
    }

    [Fact]
    public void Pedal_down_is_refused_while_the_loop_has_not_ticked_for_longer_than_the_stall_limit()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.ReportTick();
        var tick = lb.Clock.GetTimestamp();
        lb.Cycles(8, ticking: false);
        var lagMs = lb.Clock.GetElapsedTime(tick).TotalMilliseconds;
        Assert.True(lagMs > 10, $"{lagMs} ms");

        var error = Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console"));

        Assert.Equal(FormattableString.Invariant($"pedal down (console) refused: the control loop has not ticked for {lagMs:0} ms"), error.Message);
        Assert.Empty(supervisor.Trips); // at PEDAL_UP only a loop dead for the modules' torque-off stage trips

        // Exactly the stall limit (10 loop periods) since the last tick: allowed.
        supervisor.ReportTick();
        lb.Clock.Advance(10 * SupervisedLb.LoopPeriod);
        supervisor.PedalDown("console");
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
    }

    [Fact]
    public void Pedal_down_is_refused_while_a_module_is_silent_naming_it_and_its_silence()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        lb.Sim.ScheduleTransmitBreak(3, lb.Sim.Elapsed); // the right forearm's module stops answering
        lb.CyclesFor(TimeSpan.FromMilliseconds(30));
        supervisor.ReportTick(); // a cycle with a silent module lasts about 11 ms: the loop is not behind

        var error = Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("console"));

        var match = System.Text.RegularExpressions.Regex.Match(error.Message, @"^pedal down \(console\) refused: module right\.forearm has not answered for (\d+(\.\d)?) ms \(module_silent_ms 10\)$");
        Assert.True(match.Success, error.Message);
        Assert.InRange(double.Parse(match.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture), 10.1, 30); // since its last answer, after the break
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        var soft = Assert.Single(supervisor.Trips, t => t.Check == SafetyCheck.ModuleSilent); // recorded at PEDAL_UP, the level stays
        Assert.Equal(("right.forearm", true, "ms", 10.0), (soft.Joint, soft.Soft, soft.Unit, soft.Limit));
        Assert.InRange(soft.Measured, 10, 14); // not before module_silent_ms, within the cycle after it
    }

    [Fact]
    public void Pedal_up_holds_where_the_arms_are_and_is_nothing_outside_pedal_down()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.PedalUp("console"); // at PEDAL_UP: nothing
        Assert.Equal(2, supervisor.History.Count);

        supervisor.PedalDown("console");
        Assert.False(lb.Robot.IsHolding);
        var joints = new double[lb.Robot.Definition.Joints.Count];
        lb.Robot.ReadJointPositions(0, joints);
        lb.Robot.WriteJointSetpoints(0, [.. joints.Select(q => q + 0.05)]);
        lb.Cycles(40);
        supervisor.PedalUp("console");
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "console", "pedal up: holding position"), lb.LastMove);
        Assert.True(lb.Robot.IsHolding);
        lb.Cycles(2);
        var held = lb.Robot.Motors.Select(m => lb.Robot.SentGoalRad(m)).ToArray();
        lb.Cycles(40);
        Assert.Equal(held, lb.Robot.Motors.Select(m => lb.Robot.SentGoalRad(m)));

        supervisor.PedalUp("console", "lifted"); // at PEDAL_UP again: nothing
        Assert.Equal(4, supervisor.History.Count);
    }

    [Fact]
    public void Motors_off_from_pedal_down_passes_pedal_up_to_init_and_at_init_or_e_stop_only_turns_the_motors_off()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;
        supervisor.MotorsOff("console");
        Assert.Equal(
            [
                (RunLevel.PedalDown, RunLevel.PedalUp, "console", "pedal up: the motors go off"),
                (RunLevel.PedalUp, RunLevel.Init, "console", "motors off: they go on again through homing (re-homed if positions are in doubt)"),
            ],
            supervisor.History.Skip(3).Select(h => (h.From, h.To, h.Source, h.Reason)));
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);
        Assert.True(lb.Robot.IsHolding);

        supervisor.MotorsOff("console"); // at INIT: nothing more
        Assert.Equal(5, supervisor.History.Count);
        Assert.Equal("source", Assert.Throws<ArgumentException>(() => supervisor.MotorsOff(" ")).ParamName);

        // Homing again: nothing in doubt, not re-homed.
        Assert.Empty(supervisor.Home("console"));
        Assert.Equal("no module reports a lost position or a pot mismatch: not re-homed; motors on, holding", supervisor.History[^1].Reason);

        // At E_STOP with the motors held on (the operator's stop holds), they go off and the level stays.
        lb.StopNow();
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        supervisor.MotorsOff("console");
        Assert.Equal(RunLevel.EStop, supervisor.Level);
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);
    }

    [Fact]
    public void Motors_off_at_e_stop_after_a_module_fault_turns_them_off_too()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;
        lb.Stall(TimeSpan.FromMilliseconds(600)); // past the modules' torque-off stage: they switch off and latch it
        lb.Cycles(20);
        Assert.Equal((RunLevel.EStop, RobotState.Fault), (supervisor.Level, lb.Robot.State));

        supervisor.MotorsOff("console");

        Assert.Equal((RunLevel.EStop, RobotState.Discovered), (supervisor.Level, lb.Robot.State));
    }

    [Fact]
    public void An_emergency_stop_on_the_bus_thread_is_an_e_stop_at_once_with_the_operator_s_source_and_reason()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;

        using (lb.Robot.OwnBus())
        {
            supervisor.EmergencyStop("console", "E-STOP button");
            Assert.Equal((RunLevel.PedalDown, RunLevel.EStop, "console", "E-STOP button"), lb.LastMove);
        }

        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.Operator, string.Empty, 0.0, 0.0, string.Empty, SafeState.Hold, false), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        lb.Cycles(5);
        Assert.Equal(RobotState.Enabled, lb.Robot.State); // hold: the motors stay on
        Assert.False(supervisor.MotorsTrippedOff);
    }

    [Fact]
    public void An_emergency_stop_without_a_source_or_a_reason_is_refused_and_changes_nothing()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;

        Assert.Equal("reason", Assert.Throws<ArgumentException>(() => supervisor.EmergencyStop("console", " ")).ParamName);
        Assert.Equal("source", Assert.Throws<ArgumentException>(() => supervisor.EmergencyStop(" ", "stop")).ParamName);

        Assert.False(lb.Robot.IsHolding);
        Assert.False(lb.Robot.StopPending);
        lb.Cycles(3);
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
        Assert.Empty(supervisor.Trips);
    }

    [Fact]
    public void An_emergency_stop_asked_for_off_the_bus_thread_is_taken_at_the_next_check()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;
        Assert.False(lb.Robot.IsHolding);

        supervisor.EmergencyStop("cli", "E-STOP key"); // nobody owns the bus: a request

        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
        Assert.True(lb.Robot.IsHolding); // asked for at once, taken by the next write
        Assert.True(lb.Robot.StopPending);
        lb.Cycles(1);
        Assert.Equal((RunLevel.PedalDown, RunLevel.EStop, "cli", "E-STOP key"), lb.LastMove);
        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.Operator, string.Empty, string.Empty), (trip.Check, trip.Joint, trip.Unit));
        lb.Cycles(5);
        Assert.Single(supervisor.Trips);
    }

    [Fact]
    public void With_torque_off_as_the_operator_s_safe_state_an_emergency_stop_turns_the_motors_off_and_homing_turns_them_on_again()
    {
        using var lb = new SupervisedLb(SupervisedLb.WithSafeState(SafetyCheck.Operator, SafeState.TorqueOff));
        var supervisor = lb.Supervisor;
        supervisor.EmergencyStop("cli", "E-STOP key");
        lb.Cycles(1); // the write of this cycle turns the motors off, before the check records the trip
        Assert.NotEqual(RobotState.Enabled, lb.Robot.State);
        Assert.Equal(SafeState.TorqueOff, Assert.Single(supervisor.Trips).Action);
        Assert.True(supervisor.MotorsTrippedOff);
        Assert.Equal(("emergency hold", "E-STOP key"), (lb.Robot.StateHistory[^1].Source, lb.Robot.StateHistory[^1].Reason));

        supervisor.Reset("console");
        Assert.True(supervisor.MotorsTrippedOff); // until the motors go on again
        supervisor.Home("console");
        Assert.False(supervisor.MotorsTrippedOff);
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
    }

    [Fact]
    public void Every_operator_command_works_from_another_thread_while_the_bus_cycles()
    {
        using var lb = new SupervisedLb(home: false);
        var supervisor = lb.Supervisor;
        lb.FromAnotherThread(() => supervisor.Home("console"));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        lb.FromAnotherThread(() => supervisor.PedalDown("console"));
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
        lb.FromAnotherThread(() => supervisor.PedalUp("console"));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        lb.FromAnotherThread(() => supervisor.MotorsOff("console"));
        Assert.Equal(RunLevel.Init, supervisor.Level);
        supervisor.Home("console");
        lb.StopNow();
        lb.FromAnotherThread(() => supervisor.Reset("console"));
        Assert.Equal(RunLevel.Init, supervisor.Level);
    }

    [Fact]
    public void A_trip_condition_that_persists_at_e_stop_does_not_hold_up_the_operator_s_reset()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        var (elbow, axis) = lb.Motor("right.elbow");
        axis.CurrentSenseOffsetA = 2.5 * elbow.CurrentLimitA; // stays: the over-current check stays true at E_STOP
        lb.CyclesUntil(() => supervisor.Level == RunLevel.EStop, TimeSpan.FromMilliseconds(200));
        lb.Cycles(5);

        lb.FromAnotherThread(() => supervisor.Reset("console"));

        Assert.Equal(RunLevel.Init, supervisor.Level);
        Assert.Single(supervisor.Trips); // recorded once
    }

    [Fact]
    public void A_new_supervisor_makes_the_robot_hold_and_checks_its_cycles()
    {
        using var lb = new VirtualLb(start: false);
        lb.Robot.Discover();
        Assert.False(lb.Robot.IsHolding);

        var supervisor = new SafetySupervisor(lb.Robot, SupervisedLb.FileLimits, SupervisedLb.LoopPeriod);

        Assert.True(lb.Robot.IsHolding);
        Assert.Same(supervisor, lb.Robot.CycleCheck);
        Assert.Equal(RunLevel.Init, supervisor.Level);
    }

    [Fact]
    public void The_supervisor_needs_a_robot_limits_and_a_positive_loop_period()
    {
        using var lb = new SupervisedLb(home: false);
        var limits = lb.Lb.Definition.Safety;
        Assert.Equal("robot", Assert.Throws<ArgumentNullException>(() => new SafetySupervisor(null!, limits, SupervisedLb.LoopPeriod)).ParamName);
        Assert.Equal("limits", Assert.Throws<ArgumentNullException>(() => new SafetySupervisor(lb.Robot, null!, SupervisedLb.LoopPeriod)).ParamName);
        Assert.Equal("loopPeriod", Assert.Throws<ArgumentOutOfRangeException>(() => new SafetySupervisor(lb.Robot, limits, TimeSpan.Zero)).ParamName);
        Assert.Same(limits, lb.Supervisor.Limits);
        Assert.Equal(SupervisedLb.LoopPeriod, lb.Supervisor.LoopPeriod);
        Assert.Same(lb.Robot, lb.Supervisor.Robot);
    }
}
