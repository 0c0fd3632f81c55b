using RobotControl.Kinematics.ClosedForm;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Mirroring;

namespace RobotControl.Kinematics.Tests.Mirroring;

public sealed class ArmMirrorTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Fact]
    public void Left_arm_of_the_files_mirrors_in_the_x_z_plane()
    {
        var left = new ArmMirror(TestRobots.Crb);
        Assert.True(left.IsMirrored);
        Assert.Equal(Vector3d.UnitY, left.Normal);
        Assert.Equal(new Vector3d(0, 15, 0), left.BaseOffsetMm);
        Assert.Equal(new Vector3d(1, -2, 3), left.MirrorPoint(new Vector3d(1, 2, 3)));
        var right = new ArmMirror(TestRobots.Crb, "right");
        Assert.False(right.IsMirrored);
        Assert.Equal(left.BaseOffsetMm, left.MirrorPoint(right.BaseOffsetMm));
        Assert.Throws<ArgumentException>(() => new ArmMirror(TestRobots.Crb, "middle"));
    }

    [Fact]
    public void Mirrored_rotations_are_proper_and_mirroring_twice_is_the_identity()
    {
        var random = new Random(17);
        var normals = new[] { Vector3d.UnitY, new Vector3d(0.3, -1.2, 0.7) };
        foreach (var n in normals)
        {
            var mirror = new ArmMirror(n, new Vector3d(1, 2, 3));
            for (var i = 0; i < 200; i++)
            {
                var r = Rotation3d.FromRollPitchYaw(random.NextDouble() * 6 - 3, random.NextDouble() * 3 - 1.5, random.NextDouble() * 6 - 3);
                var p = new Vector3d(random.NextDouble() * 200 - 100, random.NextDouble() * 200 - 100, random.NextDouble() * 200 - 100);
                var m = mirror.MirrorRotation(r);
                Assert.Equal(1, Determinant(m), 1e-12);
                Assert.Equal(0, Vector3d.Dot(m.X, m.Y), 1e-12);
                Assert.Equal(0, Vector3d.Dot(m.Y, m.Z), 1e-12);
                Assert.Equal(1, m.X.Length, 1e-12);
                AssertClose(r, mirror.MirrorRotation(m), 1e-12);
                AssertClose(p, mirror.MirrorPoint(mirror.MirrorPoint(p)), 1e-12);
                var pose = new Pose(p, r);
                var back = mirror.ModelToBody(mirror.BodyToModel(pose));
                AssertClose(p, back.Position, 1e-12);
                AssertClose(r, back.Rotation, 1e-12);

                // A reflected point keeps its distance from the plane's other side; its component along n flips.
                Assert.Equal(-Vector3d.Dot(p, mirror.Normal), Vector3d.Dot(mirror.MirrorPoint(p), mirror.Normal), 1e-12);
            }
        }
    }

    [Fact]
    public void With_the_y_normal_a_mirrored_rotation_is_reflect_then_negate_the_y_column()
    {
        var r = Rotation3d.FromRollPitchYaw(0.3, -0.8, 1.9);
        var m = ArmMirror.Reflect(r, Vector3d.UnitY);
        static Vector3d Flip(Vector3d v) => new(v.X, -v.Y, v.Z);
        AssertClose(new Rotation3d(Flip(r.X), -Flip(r.Y), Flip(r.Z)), m, 1e-15);
    }

    [Theory]
    [MemberData(nameof(Robots))]
    public void Left_arm_reaches_the_mirror_image_of_the_right_arm(string file)
    {
        var robot = TestRobots.ByFile(file);
        var left = new ArmMirror(robot, "left");
        var right = new ArmMirror(robot, "right");
        var state = new KinematicChain(robot).CreateState();
        var q = robot.Joints.Select(j => j.MidRad).ToArray();
        state.Update(q);
        var rightBody = right.ModelToBody(state.ToolPose);
        var leftBody = left.ModelToBody(state.ToolPose);
        AssertClose(left.MirrorPoint(rightBody.Position), leftBody.Position, 1e-12);
        AssertClose(left.MirrorRotation(rightBody.Rotation), leftBody.Rotation, 1e-12);
        AssertClose(state.ToolPosition, left.BodyToModel(leftBody.Position), 1e-12);
    }

    [Fact]
    public void A_left_arm_target_solved_in_the_right_arm_model_is_reached_by_the_left_arm()
    {
        var robot = TestRobots.Crb;
        var left = new ArmMirror(robot);
        var ik = new CrbPositionIk(robot);
        var state = new KinematicChain(robot).CreateState();
        state.Update([-1.2, -0.7, 1.1, 0]);
        var bodyTarget = left.ModelToBody(state.ToolPosition); // left of the body, where the left arm works
        Assert.True(bodyTarget.Y > left.BaseOffsetMm.Y);
        var joints = new double[4];
        Assert.Equal(CrbIkStatus.Solved, ik.Solve(left.BodyToModel(bodyTarget), joints));
        state.Update(joints);
        AssertClose(bodyTarget, left.ModelToBody(state.ToolPosition), 1e-9);
    }

    [Theory]
    [MemberData(nameof(Robots))]
    public void Joint_space_mirror_reflects_the_tool_pose_and_is_an_involution(string file)
    {
        var robot = TestRobots.ByFile(file);
        var chain = new KinematicChain(robot);
        var normal = new Vector3d(robot.MirrorPlaneNormal.X, robot.MirrorPlaneNormal.Y, robot.MirrorPlaneNormal.Z);
        var mirror = new JointSpaceMirror(chain, normal);
        var state = chain.CreateState();
        var random = new Random(23);
        var q = new double[chain.JointCount];
        var mirrored = new double[chain.JointCount];
        var twice = new double[chain.JointCount];
        for (var i = 0; i < 500; i++)
        {
            for (var j = 0; j < q.Length; j++)
            {
                q[j] = random.NextDouble() * 2 * Math.PI - Math.PI;
            }

            state.Update(q);
            var expected = ArmMirror.Reflect(state.ToolPose, normal.Normalized());
            mirror.Mirror(q, mirrored);
            state.Update(mirrored);
            AssertClose(expected.Position, state.ToolPosition, 1e-9);
            AssertClose(expected.Rotation.Z, state.ToolRotation.Z, 1e-12);
            if (mirror.MatchesToolRotation)
            {
                AssertClose(expected.Rotation, state.ToolRotation, 1e-12);
            }

            mirror.Mirror(mirrored, twice);
            for (var j = 0; j < q.Length; j++)
            {
                Assert.Equal(0, Math.IEEERemainder(twice[j] - q[j], 2 * Math.PI), 1e-12);
            }
        }

        if (file == "crb-1.0.json")
        {
            Assert.Equal(new double[] { -1, 1, -1, -1 }, mirror.Signs.ToArray());
            Assert.Equal(new[] { 0, 0, 0, Math.PI }, mirror.Offsets.ToArray());
            Assert.True(mirror.MatchesToolRotation);
        }
    }

    private static double Determinant(Rotation3d r) => Vector3d.Dot(r.X, Vector3d.Cross(r.Y, r.Z));

    private static void AssertClose(Vector3d expected, Vector3d actual, double tolerance) =>
        Assert.True((expected - actual).Length <= tolerance, $"expected {expected}, found {actual}");

    private static void AssertClose(Rotation3d expected, Rotation3d actual, double tolerance)
    {
        AssertClose(expected.X, actual.X, tolerance);
        AssertClose(expected.Y, actual.Y, tolerance);
        AssertClose(expected.Z, actual.Z, tolerance);
    }
}
