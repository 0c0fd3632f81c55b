using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// What the loop's thread reports to the supervisor (pedals, the emergency-stop pedal, input ages and speeds, its
/// ticks) and what the supervisor makes of it at the next check, on a supervised virtual LB.
/// </summary>
public sealed class OperatorInputTests
{
    [Fact]
    public void A_pedal_moves_the_run_level_on_its_edges_only()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;

        supervisor.ReportPedal(true); // down from the start: not a press
        lb.Cycles(3);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        lb.PressPedal();
        Assert.Equal((RunLevel.PedalUp, RunLevel.PedalDown, "pedal", "pedal down: teleoperation drives the arms"), lb.LastMove);

        supervisor.ReportPedal(false);
        lb.Cycles(1);
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "pedal", "pedal up: holding position"), lb.LastMove);
        Assert.True(lb.Robot.IsHolding);
    }

    [Fact]
    public void After_a_soft_trip_the_pedal_must_be_lifted_and_pressed_again_and_a_press_with_stale_data_is_ignored()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        lb.PressPedal();
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);

        supervisor.ReportInputAge(0, 75); // stale right master: a soft trip back to PEDAL_UP
        lb.Cycles(1);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        supervisor.ReportInputAge(0, 1);
        lb.Cycles(3); // the pedal still down: no new press
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        supervisor.ReportInputAge(0, 75);
        lb.PressPedal(); // pressed while the data is stale: ignored, no exception on the bus thread
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        supervisor.ReportInputAge(0, 1);
        lb.PressPedal();
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
    }

    [Fact]
    public void The_emergency_stop_pedal_trips_on_its_press_once_and_a_pedal_held_through_a_reset_does_not_trip_again()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.ReportEmergencyStop(false);
        lb.Cycles(2);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        supervisor.ReportEmergencyStop(true);
        lb.Cycles(1);
        Assert.Equal((RunLevel.PedalUp, RunLevel.EStop, "pedal", "emergency-stop pedal pressed"), lb.LastMove);
        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.Operator, SafeState.Hold), (trip.Check, trip.Action));

        supervisor.Reset("console"); // the pedal still held
        lb.Cycles(3);
        Assert.Equal(RunLevel.Init, supervisor.Level);
        Assert.Single(supervisor.Trips);

        supervisor.ReportEmergencyStop(false);
        lb.Cycles(1);
        supervisor.ReportEmergencyStop(true); // a new press
        lb.Cycles(1);
        Assert.Equal(RunLevel.EStop, supervisor.Level);
        Assert.Equal(2, supervisor.Trips.Count);
    }

    [Fact]
    public void The_emergency_stop_pedal_pressed_at_an_e_stop_of_another_check_records_no_operator_trip()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.ReportEmergencyStop(false);
        lb.Cycles(1);
        var (elbow, axis) = lb.Motor("right.elbow");
        axis.CurrentSenseOffsetA = 2.5 * elbow.CurrentLimitA;
        lb.CyclesUntil(() => supervisor.Level == RunLevel.EStop, TimeSpan.FromMilliseconds(200));
        var before = supervisor.Trips.Count;

        supervisor.ReportEmergencyStop(true);
        lb.Cycles(2);

        Assert.Equal(before, supervisor.Trips.Count);
        Assert.DoesNotContain(supervisor.Trips, t => t.Check == SafetyCheck.Operator);
    }

    [Fact]
    public void A_master_speed_beyond_a_hand_s_holds_at_once_and_is_a_soft_trip_at_the_next_check_once_per_episode()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var supervisor = lb.Supervisor;
        Assert.True(supervisor.ReportInputSpeed(1, 2000)); // exactly the limit: a hand can
        Assert.False(lb.Robot.IsHolding);

        Assert.False(supervisor.ReportInputSpeed(1, 5000));
        Assert.True(lb.Robot.IsHolding); // asked for on the loop's thread, before any check
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
        lb.Cycles(1);

        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.MasterJump, "left", 5000.0, 2000.0, "mm/s", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "supervisor", "master_jump left: 5000 mm/s (limit 2000 mm/s): hold, back to PEDAL_UP"), lb.LastMove);

        // Another jump in the same episode is not recorded again; after the next pedal down it is.
        Assert.False(supervisor.ReportInputSpeed(0, double.NaN)); // NaN counts as beyond
        lb.Cycles(1);
        Assert.Single(supervisor.Trips);
        supervisor.PedalDown("console");
        lb.Cycles(2);
        Assert.Equal(RunLevel.PedalDown, supervisor.Level); // the jump before the press was taken already
        Assert.False(supervisor.ReportInputSpeed(0, 3000));
        lb.Cycles(1);
        Assert.Equal(2, supervisor.Trips.Count);
        Assert.Equal(("right", 3000.0), (supervisor.Trips[1].Joint, supervisor.Trips[1].Measured));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
    }

    [Fact]
    public void The_input_age_of_an_arm_the_robot_does_not_have_is_ignored_and_reads_0()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        Assert.Equal(0, supervisor.Inputs.AgeMs(0)); // before any report
        supervisor.ReportInputAge(0, 12.5);
        supervisor.ReportInputAge(2, 99);
        supervisor.ReportInputAge(-1, 99);
        Assert.Equal((12.5, 0.0, 0.0, 0.0), (supervisor.Inputs.AgeMs(0), supervisor.Inputs.AgeMs(1), supervisor.Inputs.AgeMs(2), supervisor.Inputs.AgeMs(-1)));
        supervisor.PedalDown("console");
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);
    }

    [Fact]
    public void A_stale_arm_at_pedal_down_is_a_soft_master_timeout_and_exactly_the_timeout_is_not()
    {
        using var lb = new SupervisedLb();
        var supervisor = lb.Supervisor;
        supervisor.PedalDown("console");
        supervisor.ReportInputAge(0, 50);
        supervisor.ReportInputAge(1, 50);
        lb.Cycles(5);
        Assert.Empty(supervisor.Trips);

        supervisor.ReportInputAge(1, 50.5);
        lb.Cycles(1);

        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.MasterTimeout, "left", 50.5, 50.0, "ms", SafeState.Hold, true), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.PedalDown, RunLevel.PedalUp, "supervisor", "master_timeout left: 50.5 ms (limit 50 ms): hold, back to PEDAL_UP"), lb.LastMove);
    }

    [Fact]
    public void Teleoperation_is_allowed_only_while_nothing_holds_and_the_bus_cycled_within_the_stall_limit()
    {
        using var lb = new SupervisedLb(home: false);
        var supervisor = lb.Supervisor;
        Assert.False(supervisor.TeleopAllowed); // holding
        supervisor.Home("console");
        supervisor.PedalDown("console");
        Assert.True(supervisor.TeleopAllowed); // no cycle timed yet

        lb.Cycles(1);
        Assert.True(supervisor.TeleopAllowed);
        lb.Clock.Advance(10 * SupervisedLb.LoopPeriod); // exactly the stall limit since the cycle's check
        Assert.True(supervisor.TeleopAllowed);
        lb.Clock.Advance(TimeSpan.FromTicks(1)); // a bus cycle late: a stall the bus thread has not seen yet
        Assert.False(supervisor.TeleopAllowed);
    }
}
