using RobotControl.Robot.Control;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The setpoints from the control loop: limited to the joint ranges, a non-finite value replaced by that joint's last
/// setpoint (the measured position right after the motors went on), bad arms and lengths refused, every refusal
/// counted until faults are cleared; the loop's hold makes the measured positions the setpoints.
/// </summary>
public sealed class SetpointExchangeTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Bad_arms_and_short_vectors_are_refused_and_counted_longer_ones_are_taken()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var setpoints = robot.Setpoints;
        var mid = robot.Definition.Joints.Select(j => j.MidRad).ToArray();

        robot.WriteJointSetpoints(2, mid);
        robot.WriteJointSetpoints(-1, mid);
        robot.WriteJointSetpoints(0, mid.AsSpan(0, 4));
        robot.WriteJawSetpoint(2, 0.1);
        robot.WriteJawSetpoint(0, double.NaN);
        robot.WriteJawSetpoint(0, double.PositiveInfinity);
        Assert.Equal(6, setpoints.Rejected);
        Assert.Equal(0, setpoints.JointVersion(0));
        Assert.Equal(0, setpoints.JawVersion(0));

        robot.WriteJointSetpoints(1, [.. mid, 1.0]); // a longer vector: its first joints are taken
        Assert.Equal(6, setpoints.Rejected);
        Assert.Equal(1, setpoints.JointVersion(1));
        Span<double> q = stackalloc double[5];
        setpoints.ReadJoints(1, q);
        Assert.Equal(mid, q.ToArray());
        Assert.True(robot.Faults.HasFlag(RobotFaults.SetpointRejected));
    }

    [Fact]
    public void Setpoints_are_limited_to_the_joint_and_jaw_ranges()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var joints = robot.Definition.Joints;
        robot.WriteJointSetpoints(0, [.. joints.Select((j, i) => i % 2 == 0 ? j.MaxRad + 1 : j.MinRad - 1)]);
        robot.WriteJawSetpoint(0, 10);
        robot.WriteJawSetpoint(1, -10);

        Span<double> q = stackalloc double[5];
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal([.. joints.Select((j, i) => i % 2 == 0 ? j.MaxRad : j.MinRad)], q.ToArray());
        Span<double> jaw = stackalloc double[1];
        robot.Setpoints.ReadJaw(0, jaw);
        Assert.Equal(robot.Map.JawMaxRad, jaw[0]);
        robot.Setpoints.ReadJaw(1, jaw);
        Assert.Equal(robot.Map.JawMinRad, jaw[0]);
        Assert.Equal(0, robot.Setpoints.Rejected);
        Assert.Equal(RobotFaults.None, robot.Faults & RobotFaults.SetpointRejected);
    }

    [Fact]
    public void A_non_finite_joint_keeps_its_last_setpoint_and_after_the_motors_go_on_its_measured_position()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var mid = robot.Definition.Joints.Select(j => j.MidRad).ToArray();
        var a = mid.Select((v, i) => v + ((i + 1) * Deg)).ToArray();
        Span<double> q = stackalloc double[5];

        robot.WriteJointSetpoints(0, a);
        robot.WriteJointSetpoints(0, [double.NaN, a[1] + Deg, a[2], a[3], a[4]]);
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal([a[0], a[1] + Deg, a[2], a[3], a[4]], q.ToArray());
        Assert.Equal(1, robot.Setpoints.Rejected);
        robot.WriteJointSetpoints(0, [a[0], double.NaN, a[2], a[3], a[4]]);
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal(a[1] + Deg, q[1]); // the last published value, not the first

        // The motors go on again: the measured positions are the last setpoints a refused value falls back to.
        rig.Cycles(5);
        robot.EnableTorque(false);
        robot.EnableTorque(true);
        Span<double> measured = stackalloc double[5];
        robot.ReadJointPositions(0, measured);
        robot.WriteJointSetpoints(0, [double.NaN, double.NaN, double.NaN, double.NaN, double.PositiveInfinity]);
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal(measured.ToArray(), q.ToArray());
        Assert.Equal(3, robot.Setpoints.Rejected);

        // Only once per seed: the next refusal falls back to the setpoint just published.
        robot.WriteJointSetpoints(0, a);
        rig.Cycles(2);
        robot.WriteJointSetpoints(0, [double.NaN, a[1], a[2], a[3], a[4]]);
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal(a[0], q[0]);
    }

    [Fact]
    public void Refusals_show_as_a_fault_until_faults_are_cleared()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var mid = robot.Definition.Joints.Select(j => j.MidRad).ToArray();
        robot.WriteJointSetpoints(0, [double.NaN, .. mid[1..]]);
        Assert.True(robot.Faults.HasFlag(RobotFaults.SetpointRejected));

        robot.ClearFaults();
        rig.Cycles(1);
        Assert.False(robot.Faults.HasFlag(RobotFaults.SetpointRejected));
        robot.WriteJawSetpoint(1, double.NaN);
        Assert.True(robot.Faults.HasFlag(RobotFaults.SetpointRejected));
    }

    [Fact]
    public void The_loops_hold_makes_the_measured_positions_the_setpoints_and_stops_a_jogging_motor()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var far = robot.Definition.Joints.Select(j => j.MidRad + (0.3 * (j.MaxRad - j.MidRad))).ToArray();
        robot.WriteJointSetpoints(0, far);
        robot.WriteJointSetpoints(1, far);
        robot.WriteJawSetpoint(0, robot.Map.JawMaxRad);
        var roll = robot.Motor("left.tool_roll");
        roll.Jog(0.5);
        rig.Cycles(40);

        robot.HoldPosition();

        Span<double> q = stackalloc double[5];
        Span<double> p = stackalloc double[5];
        Span<double> jaw = stackalloc double[1];
        var held = new double[2][];
        for (var arm = 0; arm < 2; arm++)
        {
            robot.Setpoints.ReadJoints(arm, q);
            robot.ReadJointPositions(arm, p);
            Assert.Equal(p.ToArray(), q.ToArray());
            held[arm] = q.ToArray();
            robot.Setpoints.ReadJaw(arm, jaw);
            Assert.Equal(robot.Motor(arm == 0 ? "right.tool_open_close" : "left.tool_open_close").PositionRad, jaw[0]);
        }

        // The jogging motor stops where it was (its goal returns there under the step cap, and stays).
        var rollHeld = Math.Clamp(roll.PositionRad, roll.Config.OutputMinRad, roll.Config.OutputMaxRad);
        rig.Cycles(100);
        Assert.Equal(rollHeld, robot.SentGoalRad(roll));
        rig.Cycles(10);
        Assert.Equal(rollHeld, robot.SentGoalRad(roll));

        // The held positions are also what a refused value falls back to.
        robot.WriteJointSetpoints(0, [double.NaN, .. far[1..]]);
        robot.Setpoints.ReadJoints(0, q);
        Assert.Equal(held[0][0], q[0]);
    }

    [Fact]
    public void The_bus_thread_reads_each_arms_setpoints_once_per_write_as_written()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var mid = robot.Definition.Joints.Select(j => j.MidRad).ToArray();
        var right = mid.Select(v => v + (2 * Deg)).ToArray();
        var left = mid.Select(v => v - (2 * Deg)).ToArray();
        robot.WriteJointSetpoints(0, right);
        robot.WriteJointSetpoints(1, left);
        var seen = new List<(int Arm, double[] Q)>();
        robot.Setpoints.Observer = (arm, q) => seen.Add((arm, q.ToArray()));

        rig.Cycles(3);

        Assert.Equal([0, 1, 0, 1, 0, 1], seen.Select(s => s.Arm));
        Assert.All(seen, s => Assert.Equal(s.Arm == 0 ? right : left, s.Q));
    }
}
