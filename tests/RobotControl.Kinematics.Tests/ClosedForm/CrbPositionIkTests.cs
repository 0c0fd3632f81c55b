using System.Text.Json.Nodes;
using RobotControl.Definitions.Loading;
using RobotControl.Kinematics.ClosedForm;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Tests.ClosedForm;

public sealed class CrbPositionIkTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Round_trips_over_a_grid_of_the_joint_ranges()
    {
        var robot = TestRobots.Crb;
        var ik = new CrbPositionIk(robot);
        var state = new KinematicChain(robot).CreateState();
        var q = new double[4];
        var solved = new double[4];
        var worstPosition = 0.0;
        var worstJointRegular = 0.0;
        var worstJointNearSingular = 0.0;
        var count = 0;
        for (var yaw = -90.0; yaw <= 45; yaw += 5)
        {
            for (var pitch = -90.0; pitch <= 45; pitch += 5)
            {
                for (var elbow = 0.0; elbow <= 105; elbow += 5)
                {
                    q[0] = yaw * Deg;
                    q[1] = pitch * Deg;
                    q[2] = elbow * Deg;
                    q[3] = 0.4;
                    state.Update(q);
                    var target = state.ToolPosition;
                    solved[0] = double.NaN;
                    solved[3] = 0.4;
                    var status = ik.Solve(target, solved);
                    if (status != CrbIkStatus.Solved)
                    {
                        Assert.Fail($"{status} for q = ({yaw}, {pitch}, {elbow}) deg, target {target}");
                    }

                    for (var j = 0; j < 3; j++)
                    {
                        if (solved[j] < robot.Joints[j].MinRad || solved[j] > robot.Joints[j].MaxRad)
                        {
                            Assert.Fail($"joint {j} = {solved[j]} is outside its range");
                        }
                    }

                    state.Update(solved);
                    worstPosition = Math.Max(worstPosition, (state.ToolPosition - target).Length);
                    var jointError = Math.Max(Math.Abs(solved[0] - q[0]), Math.Max(Math.Abs(solved[1] - q[1]), Math.Abs(solved[2] - q[2])));
                    var straightElbow = elbow == 0;
                    var pointingDown = pitch == -90;
                    if (straightElbow && pointingDown)
                    {
                        // On the yaw axis: the yaw is free, only pitch and elbow are determined.
                        jointError = Math.Max(Math.Abs(solved[1] - q[1]), Math.Abs(solved[2] - q[2]));
                    }

                    if (straightElbow || pointingDown)
                    {
                        worstJointNearSingular = Math.Max(worstJointNearSingular, jointError);
                    }
                    else
                    {
                        worstJointRegular = Math.Max(worstJointRegular, jointError);
                    }

                    if (solved[3] != 0.4)
                    {
                        Assert.Fail("the tool roll was overwritten");
                    }

                    count++;
                }
            }
        }

        Assert.Equal(28 * 28 * 22, count); // 5° steps over -90..45, -90..45, 0..105
        Assert.True(worstPosition <= 1e-9, $"largest position error {worstPosition} mm");
        Assert.True(worstJointRegular <= 1e-9, $"largest joint error away from singularities {worstJointRegular} rad");
        // At a singularity (straight elbow, or pointing straight down) the inverse is square-root conditioned: the
        // yaw/pitch split is known to about sqrt(rounding) · L / (L2 sin elbow), the position still to rounding.
        Assert.True(worstJointNearSingular <= 1e-5, $"largest joint error at singularities {worstJointNearSingular} rad");
    }

    [Fact]
    public void Lengths_come_from_the_DH_table_of_the_file()
    {
        var robot = TestRobots.Crb;
        var ik = new CrbPositionIk(robot);
        Assert.Equal(68.58, ik.UpperArmMm);
        Assert.Equal(96.393, ik.ForearmMm);

        var json = JsonNode.Parse(File.ReadAllText(TestRobots.PathOf("crb-1.0.json")))!;
        json["dh"]![2]!["a_mm"] = 80.0;
        json["dh"]![4]!["d_mm"] = 120.0;
        var changed = RobotLoader.LoadFromText(json.ToJsonString(), TestRobots.PathOf("crb-longer-arms.json"));
        var longer = new CrbPositionIk(changed);
        Assert.Equal(80.0, longer.UpperArmMm);
        Assert.Equal(120.0, longer.ForearmMm);
        var state = new KinematicChain(changed).CreateState();
        double[] q = [0.2, -0.5, 1.0, 0];
        state.Update(q);
        var solved = new double[4];
        Assert.Equal(CrbIkStatus.Solved, longer.Solve(state.ToolPosition, solved));
        Assert.Equal(q[..3], solved[..3], (a, b) => Math.Abs(a - b) < 1e-9);
    }

    [Fact]
    public void Unreachable_targets_fail_without_writing_the_joints()
    {
        var ik = new CrbPositionIk(TestRobots.Crb);
        var reach = ik.UpperArmMm + ik.ForearmMm;
        var joints = new double[] { 7, 7, 7, 7 };
        Assert.Equal(CrbIkStatus.OutOfReach, ik.Solve(new Vector3d(reach + 1e-6, 0, 0), joints));
        Assert.Equal(CrbIkStatus.OutOfReach, ik.Solve(new Vector3d(0, 300, 0), joints));
        Assert.Equal(CrbIkStatus.TooClose, ik.Solve(new Vector3d(10, 0, 0), joints));
        Assert.Equal(CrbIkStatus.TooClose, ik.Solve(Vector3d.Zero, joints));
        Assert.Equal(CrbIkStatus.JointLimit, ik.Solve(new Vector3d(-120, 0, 0), joints)); // behind the shoulder
        Assert.Equal(CrbIkStatus.JointLimit, ik.Solve(new Vector3d(0, 0, 150), joints)); // straight up: pitch +90
        Assert.Equal(CrbIkStatus.InvalidTarget, ik.Solve(new Vector3d(double.NaN, 0, 0), joints));
        Assert.Equal(CrbIkStatus.InvalidTarget, ik.Solve(new Vector3d(double.PositiveInfinity, 0, 0), joints));
        Assert.All(joints, v => Assert.Equal(7, v));
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(new Vector3d(reach, 0, 0), joints));
        Assert.All(joints.Take(3), v => Assert.Equal(0, v, 1e-6));
    }

    [Fact]
    public void Straight_down_keeps_the_free_yaw()
    {
        var ik = new CrbPositionIk(TestRobots.Crb);
        var joints = new double[] { 0.3, 0, 0, 0 };
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(new Vector3d(0, 0, -(ik.UpperArmMm + ik.ForearmMm)), joints));
        Assert.Equal(0.3, joints[0]);
        Assert.Equal(-Math.PI / 2, joints[1], 1e-12);
        Assert.Equal(0, joints[2], 1e-6);
    }

    [Fact]
    public void Refuses_a_chain_that_is_not_a_CRB_arm()
    {
        Assert.Throws<ArgumentException>(() => new CrbPositionIk(TestRobots.Lb));
        Assert.Throws<ArgumentNullException>(() => new CrbPositionIk(null!));
    }

    // One change at a time to the CRB-1.0's DH table (rows counted from 1): the closed form must refuse each, naming the row.
    [Theory]
    [InlineData(0, "alpha_deg", 10.0, "DH row 1 must be")]
    [InlineData(0, "a_mm", 1.0, "DH row 1 must be")]
    [InlineData(0, "d_mm", 1.0, "DH row 1 must be")]
    [InlineData(0, "theta_offset_deg", 5.0, "DH row 1 must be")]
    [InlineData(1, "d_mm", 1.0, "DH row 2 must be")]
    [InlineData(2, "theta_offset_deg", 5.0, "DH row 3 must be")]
    [InlineData(3, "alpha_deg", -90.0, "DH row 4 must be")]
    [InlineData(3, "a_mm", 1.0, "DH row 4 must be")]
    [InlineData(1, "alpha_deg", -90.0, "DH row 2 must be")]
    [InlineData(1, "theta_offset_deg", 5.0, "DH row 2 must be")]
    [InlineData(1, "a_mm", 3.0, "DH row 2 must be")]
    [InlineData(2, "alpha_deg", 90.0, "DH row 3 must be")]
    [InlineData(2, "d_mm", 2.0, "DH row 3 must be")]
    [InlineData(2, "a_mm", 0.0, "DH row 3 must have a = L1 > 0")]
    [InlineData(3, "theta_offset_deg", 0.0, "DH row 4 must be")]
    [InlineData(3, "d_mm", 1.0, "DH row 4 must be")]
    [InlineData(4, "a_mm", 1.0, "DH row 5 must be the tool roll")]
    [InlineData(4, "d_mm", 0.0, "DH row 5 must be the tool roll")]
    public void Refuses_each_departure_from_the_CRB_structure_naming_the_row(int row, string field, double value, string message)
    {
        var json = JsonNode.Parse(File.ReadAllText(TestRobots.PathOf("crb-1.0.json")))!;
        json["dh"]![row]![field] = value;
        var changed = RobotLoader.LoadFromText(json.ToJsonString(), TestRobots.PathOf("crb-changed.json"));
        Assert.Contains(message, Assert.Throws<ArgumentException>(() => new CrbPositionIk(changed)).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Refuses_a_table_of_another_length_saying_how_many_rows_it_found()
    {
        var message = Assert.Throws<ArgumentException>(() => new CrbPositionIk(TestRobots.Lb)).Message;
        Assert.Contains("the CRB closed form needs 5 DH rows, found 6", message, StringComparison.Ordinal);
    }

    // Ranges that leave no elbow-up (elbow in 0..180°), non-inverted (pitch in -90..90°) solution, each refused.
    [Theory]
    [InlineData(1, 100.0, 120.0)]
    [InlineData(1, -120.0, -100.0)]
    [InlineData(2, -20.0, -10.0)]
    public void Refuses_joint_ranges_that_leave_no_elbow_up_non_inverted_solution(int joint, double minDeg, double maxDeg)
    {
        var changed = WithRange(joint, minDeg, maxDeg);
        var message = Assert.Throws<ArgumentException>(() => new CrbPositionIk(changed)).Message;
        Assert.Contains("the joint ranges leave no elbow-up, non-inverted solution", message, StringComparison.Ordinal);
    }

    [Fact]
    public void An_elbow_range_ending_at_0_leaves_the_straight_arm_only()
    {
        var ik = new CrbPositionIk(WithRange(2, -10, 0));
        Assert.Equal(ik.UpperArmMm + ik.ForearmMm, ik.MaxReachMm, 12);
        Assert.Equal(ik.UpperArmMm + ik.ForearmMm, ik.MinReachMm, 12);
    }

    [Fact]
    public void A_pitch_range_starting_at_90_degrees_leaves_the_arm_pointing_straight_up()
    {
        var robot = WithRange(1, 90, 120);
        var ik = new CrbPositionIk(robot);
        var joints = new double[4];
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(new Vector3d(0, 0, ik.UpperArmMm + ik.ForearmMm), joints));
        Assert.Equal(robot.Joints[1].MinRad, joints[1], 12);
    }

    [Fact]
    public void The_reach_follows_the_law_of_cosines_over_the_elbow_range()
    {
        // Elbow 30..105°: |p|² = L1² + L2² + 2 L1 L2 cos(elbow), largest at 30°, smallest at 105°.
        var ik = new CrbPositionIk(WithRange(2, 30, 105));
        double Reach(double elbowDeg) => Math.Sqrt((68.58 * 68.58) + (96.393 * 96.393) + (2 * 68.58 * 96.393 * Math.Cos(elbowDeg * Deg)));
        Assert.Equal(Reach(30), ik.MaxReachMm, 9);
        Assert.Equal(Reach(105), ik.MinReachMm, 9);
    }

    [Fact]
    public void A_pitch_range_above_the_horizontal_refuses_a_horizontal_target_and_solves_one_within_it()
    {
        var robot = WithRange(1, 10, 45);
        var ik = new CrbPositionIk(robot);
        var state = new KinematicChain(robot).CreateState();
        var joints = new double[4];
        state.Update([0.2, 0, 0.5, 0]); // pitch 0, below the range
        Assert.Equal(CrbIkStatus.JointLimit, ik.Solve(state.ToolPosition, joints));
        state.Update([0.2, 20 * Deg, 0.5, 0]);
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(state.ToolPosition, joints));
        Assert.Equal([0.2, 20 * Deg, 0.5], joints[..3], (a, b) => Math.Abs(a - b) < 1e-9);
    }

    [Fact]
    public void Needs_room_for_exactly_the_three_position_joints()
    {
        var ik = new CrbPositionIk(TestRobots.Crb);
        var state = new KinematicChain(TestRobots.Crb).CreateState();
        state.Update([0.1, -0.2, 0.9, 0]);
        var three = new double[3];
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(state.ToolPosition, three));
        Assert.Equal([0.1, -0.2, 0.9], three, (a, b) => Math.Abs(a - b) < 1e-9);
        Assert.Throws<ArgumentException>(() => ik.Solve(state.ToolPosition, new double[2]));
    }

    [Fact]
    public void At_the_least_reach_the_elbow_is_exactly_on_its_limit()
    {
        var robot = TestRobots.Crb;
        var ik = new CrbPositionIk(robot);
        var state = new KinematicChain(robot).CreateState();
        state.Update([0.2, -0.3, robot.Joints[2].MaxRad, 0]);
        var joints = new double[4];
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(state.ToolPosition, joints));
        Assert.Equal(robot.Joints[2].MaxRad, joints[2]);
        Assert.Equal(0.2, joints[0], 9);
        Assert.Equal(-0.3, joints[1], 9);
    }

    [Fact]
    public void Pointing_nearly_down_with_the_elbow_straight_the_yaw_comes_from_the_target_not_the_seed()
    {
        // 0.2° off the vertical: the tool sits (L1 + L2) sin 0.2° ≈ 0.58 mm from the yaw axis, far above rounding.
        var robot = TestRobots.Crb;
        var ik = new CrbPositionIk(robot);
        var state = new KinematicChain(robot).CreateState();
        state.Update([0.3, -89.8 * Deg, 0, 0]);
        var joints = new double[4];
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(state.ToolPosition, joints));
        Assert.Equal(0.3, joints[0], 9);
        Assert.Equal(-89.8 * Deg, joints[1], 9);
    }

    private static Definitions.Model.RobotDefinition WithRange(int joint, double minDeg, double maxDeg)
    {
        var json = JsonNode.Parse(File.ReadAllText(TestRobots.PathOf("crb-1.0.json")))!;
        json["joints"]![joint]!["min_deg"] = minDeg;
        json["joints"]![joint]!["max_deg"] = maxDeg;
        return RobotLoader.LoadFromText(json.ToJsonString(), TestRobots.PathOf("crb-ranges.json"));
    }

    [Fact]
    public void Is_allocation_free()
    {
        var ik = new CrbPositionIk(TestRobots.Crb);
        var joints = new double[4];
        var state = new KinematicChain(TestRobots.Crb).CreateState();
        state.Update([-0.4, -0.6, 1.2, 0]);
        var target = state.ToolPosition;
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(target, joints));
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 100; i++)
        {
            ik.Solve(target, joints);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }
}
