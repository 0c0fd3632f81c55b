using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// The per-motor checks on a supervised virtual LB: each condition trips once it has lasted its time, measured from
/// the first check that saw it (found here by evaluating the same condition after every cycle); a host stall's part
/// beyond the stall limit does not count toward that time; a reset forgets it.
/// </summary>
public sealed class MotorCheckTests
{
    private const string Elbow = "right.elbow";

    [Fact]
    public void An_over_current_trips_when_it_has_lasted_over_current_ms_and_turns_the_motors_off()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var (motor, axis) = lb.Motor(Elbow);
        axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA;

        var trip = AssertPersists(lb, SafetyCheck.OverCurrent, 50, OverCurrent(lb));

        Assert.Equal((Elbow, 0.95 * 0.08, "A", SafeState.TorqueOff, false), (trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.True(trip.Measured > trip.Limit);
        Assert.Equal((RunLevel.EStop, "over_current right.elbow: torque_off"), (lb.Supervisor.Level, lb.LastMove.Reason));
        lb.Cycles(1);
        Assert.Equal(("emergency hold", "over_current right.elbow: torque_off"), (lb.Robot.StateHistory[^1].Source, lb.Robot.StateHistory[^1].Reason));
    }

    [Fact]
    public void An_over_current_shorter_than_its_time_trips_nothing_and_starts_again_from_nothing()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var (motor, axis) = lb.Motor(Elbow);
        for (var i = 0; i < 3; i++)
        {
            axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA;
            lb.CyclesUntil(OverCurrent(lb), TimeSpan.FromMilliseconds(50));
            lb.CyclesFor(TimeSpan.FromMilliseconds(35));
            axis.CurrentSenseOffsetA = 0;
            lb.CyclesUntil(() => !OverCurrent(lb)(), TimeSpan.FromMilliseconds(50));
        }

        Assert.Empty(lb.Supervisor.Trips);
    }

    [Fact]
    public void A_tracking_error_trips_when_it_has_lasted_tracking_error_ms_and_holds()
    {
        // The current check relaxed: a stuck elbow trips its tracking error first.
        using var lb = SupervisedLb.AtPedalDown(SupervisedLb.FileLimits with { TrackingErrorRad = 0.05, TrackingErrorMs = 20, CurrentLimitFraction = 100 });
        StickElbow(lb);

        var trip = AssertPersists(lb, SafetyCheck.TrackingError, 20, TrackingError(lb, 0.05));

        Assert.Equal((Elbow, 0.05, "rad", SafeState.Hold, false), (trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.True(trip.Measured > 0.05);
        Assert.Equal((RunLevel.EStop, "tracking_error right.elbow: hold"), (lb.Supervisor.Level, lb.LastMove.Reason));
    }

    [Fact]
    public void A_pot_mismatch_trips_when_it_has_lasted_pot_mismatch_ms_and_turns_the_motors_off()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Motor(Elbow).Axis.PotFailedRaw = 0;

        var trip = AssertPersists(lb, SafetyCheck.PotMismatch, 10, PotMismatch(lb, 5 * Math.PI / 180));

        Assert.Equal((Elbow, 5 * Math.PI / 180, "rad", SafeState.TorqueOff, false), (trip.Joint, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.True(trip.Measured > trip.Limit);
    }

    [Fact]
    public void The_part_of_a_soft_stall_beyond_the_stall_limit_does_not_count_toward_an_over_current_s_time()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var (motor, axis) = lb.Motor(Elbow);
        axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA;
        AssertPersists(lb, SafetyCheck.OverCurrent, 50, OverCurrent(lb), stallAfterOnsetMs: 100);
    }

    [Fact]
    public void The_part_of_a_soft_stall_beyond_the_stall_limit_does_not_count_toward_a_tracking_error_s_time()
    {
        using var lb = SupervisedLb.AtPedalDown(SupervisedLb.FileLimits with { TrackingErrorRad = 0.05, TrackingErrorMs = 40, CurrentLimitFraction = 100 });
        StickElbow(lb);
        AssertPersists(lb, SafetyCheck.TrackingError, 40, TrackingError(lb, 0.05), stallAfterOnsetMs: 100);
    }

    [Fact]
    public void The_part_of_a_soft_stall_beyond_the_stall_limit_does_not_count_toward_a_pot_mismatch_s_time()
    {
        using var lb = SupervisedLb.AtPedalDown(SupervisedLb.FileLimits with { PotMismatchMs = 40 });
        lb.Motor(Elbow).Axis.PotFailedRaw = 0;
        AssertPersists(lb, SafetyCheck.PotMismatch, 40, PotMismatch(lb, 5 * Math.PI / 180), stallAfterOnsetMs: 100);
    }

    [Fact]
    public void After_a_soft_stall_a_new_over_current_still_takes_its_whole_time()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Stall(TimeSpan.FromMilliseconds(100));
        lb.Cycles(3);
        Assert.Equal(SafetyCheck.HostStall, Assert.Single(lb.Supervisor.Trips).Check);
        var (motor, axis) = lb.Motor(Elbow);
        axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA;

        AssertPersists(lb, SafetyCheck.OverCurrent, 50, OverCurrent(lb));
    }

    [Fact]
    public void A_reset_forgets_how_long_an_over_current_has_lasted()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var (motor, axis) = lb.Motor(Elbow);
        axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA; // stays through the reset and homing
        lb.CyclesUntil(OverCurrent(lb), TimeSpan.FromMilliseconds(50));
        lb.CyclesFor(TimeSpan.FromMilliseconds(30));
        using (lb.Robot.OwnBus())
        {
            lb.Supervisor.EmergencyStop("console", "stop");
            lb.Supervisor.Reset("console");
        }

        lb.Supervisor.Home("console");
        Assert.Equal(RunLevel.PedalUp, lb.Supervisor.Level);

        AssertPersists(lb, SafetyCheck.OverCurrent, 50, OverCurrent(lb));
    }

    [Fact]
    public void After_an_e_stop_from_a_stall_a_pot_that_does_not_confirm_its_motor_s_position_means_re_homing()
    {
        using var lb = SupervisedLb.AtPedalDown();
        var (motor, axis) = lb.Motor(Elbow);
        axis.PotFailedRaw = 0;
        lb.CyclesUntil(PotMismatch(lb, 5 * Math.PI / 180), TimeSpan.FromMilliseconds(100));
        lb.Stall(TimeSpan.FromMilliseconds(600)); // before the mismatch has lasted its 10 ms
        lb.Cycles(20);
        Assert.Equal([SafetyCheck.HostStall, SafetyCheck.ModuleFault], lb.Supervisor.Trips.Select(t => t.Check));
        Assert.True(Math.Abs(motor.PotPositionRad - motor.PositionAtPotRad) > 0.5);

        lb.Supervisor.Reset("console");
        var homed = lb.Supervisor.Home("console");

        Assert.Equal(12, homed.Count);
        Assert.Equal("12 motors homed and verified (1 had lost their position); motors on, holding", lb.LastMove.Reason);
    }

    [Fact]
    public void After_an_e_stop_from_a_stall_and_another_trip_every_motor_is_homed_again()
    {
        using var lb = SupervisedLb.AtPedalDown();
        lb.Stall(TimeSpan.FromMilliseconds(600));
        lb.Cycles(20);
        var (motor, axis) = lb.Motor(Elbow);
        axis.CurrentSenseOffsetA = 2.5 * motor.CurrentLimitA; // an over-current at E_STOP: not a silence
        lb.CyclesUntil(() => lb.Supervisor.Trips.Any(t => t.Check == SafetyCheck.OverCurrent), TimeSpan.FromMilliseconds(200));
        axis.CurrentSenseOffsetA = 0;

        lb.Supervisor.Reset("console");
        var homed = lb.Supervisor.Home("console");

        Assert.Equal(12, homed.Count);
        Assert.Equal("12 motors homed and verified (after a reset); motors on, holding", lb.LastMove.Reason);
    }

    /// <summary>
    /// Runs cycles until <paramref name="beyond"/> (the check's condition, as the supervisor evaluates it) first holds,
    /// optionally 5 ms more and a soft stall of <paramref name="stallAfterOnsetMs"/>, then until <paramref name="check"/>
    /// trips: at the first check at least <paramref name="persistMs"/> after the condition began, not counting the
    /// stall's part beyond the stall limit (10 ms); returns the trip.
    /// </summary>
    private static SafetyTrip AssertPersists(SupervisedLb lb, SafetyCheck check, double persistMs, Func<bool> beyond, double stallAfterOnsetMs = 0)
    {
        var supervisor = lb.Supervisor;
        lb.Cycles(1); // a condition true before is seen by the next check
        lb.CyclesUntil(beyond, TimeSpan.FromMilliseconds(200));
        var since = lb.Now; // the time of the check that saw it first (nothing passes on the bus clock after a check)
        var uncounted = 0.0;
        if (stallAfterOnsetMs > 0)
        {
            lb.CyclesFor(TimeSpan.FromMilliseconds(5));
            Assert.True(beyond());
            lb.Stall(TimeSpan.FromMilliseconds(stallAfterOnsetMs));
            lb.Cycles(1);
            var stall = supervisor.Trips.Single(t => t.Check == SafetyCheck.HostStall);
            Assert.True(stall.Soft);
            uncounted = stall.Measured - 10;
        }

        lb.CyclesUntil(() => supervisor.Trips.Any(t => t.Check == check), TimeSpan.FromMilliseconds(persistMs + uncounted + 50));
        var trip = supervisor.Trips.Single(t => t.Check == check);
        var counted = ((supervisor.Seconds(trip.Timestamp) - since) * 1e3) - uncounted;
        Assert.InRange(counted, persistMs - 1e-6, persistMs + 5); // the first check after its time (a cycle with polls lasts up to about 4 ms)
        return trip;
    }

    private static Func<bool> OverCurrent(SupervisedLb lb)
    {
        var m = lb.Robot.Motor(Elbow);
        return () => Math.Abs(m.CurrentA) > 0.95 * m.CurrentLimitA;
    }

    private static Func<bool> TrackingError(SupervisedLb lb, double limit)
    {
        var m = lb.Robot.Motor(Elbow);
        return () => Math.Abs(lb.Robot.SentGoalRad(m) - m.PositionRad) > limit;
    }

    private static Func<bool> PotMismatch(SupervisedLb lb, double limit)
    {
        var m = lb.Robot.Motor(Elbow);
        return () => double.IsFinite(m.PotPositionRad) && Math.Abs(m.PotPositionRad - m.PositionAtPotRad) > limit;
    }

    /// <summary>The right elbow against an obstacle its drive cannot move, asked to go 0.4 rad further.</summary>
    private static void StickElbow(SupervisedLb lb)
    {
        lb.Motor(Elbow).Axis.ObstacleTorqueNm = 5;
        var joints = new double[lb.Robot.Definition.Joints.Count];
        lb.Robot.ReadJointPositions(0, joints);
        joints[3] += 0.4;
        lb.Robot.WriteJointSetpoints(0, joints);
    }
}
