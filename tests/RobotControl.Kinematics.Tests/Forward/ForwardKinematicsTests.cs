using MathNet.Numerics.LinearAlgebra;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Tests.Forward;

public sealed class ForwardKinematicsTests
{
    private const double Deg = Math.PI / 180;

    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void Recursion_matches_the_product_of_DH_matrices_on_1000_random_joint_vectors(string file)
    {
        var robot = TestRobots.ByFile(file);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var random = new Random(20261122);
        var q = new double[chain.JointCount];
        var worstPosition = 0.0;
        var worstRotation = 0.0;
        for (var sample = 0; sample < 1000; sample++)
        {
            for (var j = 0; j < q.Length; j++)
            {
                q[j] = (random.NextDouble() * 2 - 1) * Math.PI;
            }

            state.Update(q);
            var t = DhMatrix.ToolTransform(chain, q);
            var p = state.ToolPosition;
            var r = state.ToolRotation;
            worstPosition = Math.Max(worstPosition, Math.Abs(p.X - t[0, 3]) + Math.Abs(p.Y - t[1, 3]) + Math.Abs(p.Z - t[2, 3]));
            for (var row = 0; row < 3; row++)
            {
                for (var col = 0; col < 3; col++)
                {
                    worstRotation = Math.Max(worstRotation, Math.Abs(r.At(row, col) - t[row, col]));
                }
            }

            Assert.Equal(new[] { 0.0, 0, 0, 1 }, t.Row(3).ToArray());
        }

        Assert.True(worstPosition < 1e-9, $"largest position difference {worstPosition} mm");
        Assert.True(worstRotation < 1e-12, $"largest rotation difference {worstRotation}");
    }

    [Fact]
    public void Dh_row_transform_is_the_closed_form_standard_DH_matrix()
    {
        var row = new Definitions.Model.DhRow(0.3, 12.5, -4.0, 0.2, 0);
        var q = 0.7;
        var t = DhMatrix.RowTransform(row, q);
        var (st, ct) = Math.SinCos(q + 0.2);
        var (sa, ca) = Math.SinCos(0.3);
        var expected = Matrix<double>.Build.DenseOfArray(new[,]
        {
            { ct, -st * ca, st * sa, 12.5 * ct },
            { st, ct * ca, -ct * sa, 12.5 * st },
            { 0, sa, ca, -4.0 },
            { 0, 0, 0, 1 },
        });
        Assert.True((t - expected).InfinityNorm() < 1e-15);
    }

    [Fact]
    public void Crb_tool_is_at_L1_plus_L2_along_x_at_zero_and_points_down_at_pitch_minus_90()
    {
        var robot = TestRobots.Crb;
        var reach = robot.Dh[2].AMm + robot.Dh[4].DMm;
        var state = new KinematicChain(robot).CreateState();

        state.Update([0, 0, 0, 0]);
        AssertClose(new Vector3d(reach, 0, 0), state.ToolPosition, 1e-12);
        AssertClose(Vector3d.UnitX, state.ToolRotation.Z, 1e-15);

        state.Update([0, -90 * Deg, 0, 0]);
        AssertClose(new Vector3d(0, 0, -reach), state.ToolPosition, 1e-12);
        AssertClose(-Vector3d.UnitZ, state.ToolRotation.Z, 1e-15);

        // phi1 is a yaw about the base z axis.
        state.Update([30 * Deg, 0, 0, 0]);
        AssertClose(new Vector3d(reach * Math.Cos(30 * Deg), reach * Math.Sin(30 * Deg), 0), state.ToolPosition, 1e-12);
    }

    [Fact]
    public void Lb_tool_position_matches_its_lengths_at_zero()
    {
        var robot = TestRobots.Lb;
        var state = new KinematicChain(robot).CreateState();
        state.Update(new double[robot.JointCount]);
        var t = DhMatrix.ToolTransform(robot.Dh, new double[robot.JointCount]);
        AssertClose(DhMatrix.ToPose(t).Position, state.ToolPosition, 1e-12);
        Assert.Equal(87.57 + 86.59, state.ToolPosition.Length, 9);
    }

    [Theory]
    [MemberData(nameof(Robots))]
    public void Jacobian_matches_central_finite_differences(string file)
    {
        var robot = TestRobots.ByFile(file);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var n = chain.JointCount;
        var jacobian = new double[6 * n];
        var q = new double[n];
        var random = new Random(7);
        const double h = 1e-6;
        for (var sample = 0; sample < 50; sample++)
        {
            TestRobots.FillRandomJoints(chain, random, q);

            state.Update(q);
            state.Jacobian(jacobian);
            for (var j = 0; j < n; j++)
            {
                var saved = q[j];
                q[j] = saved + h;
                state.Update(q);
                var pPlus = state.ToolPosition;
                var rPlus = state.ToolRotation;
                q[j] = saved - h;
                state.Update(q);
                var pMinus = state.ToolPosition;
                var rMinus = state.ToolRotation;
                q[j] = saved;
                state.Update(q);
                var r = state.ToolRotation;

                var velocity = (pPlus - pMinus) / (2 * h);
                var omega = AngularVelocity(rPlus, rMinus, r, h);
                Assert.Equal(velocity.X, jacobian[j], 1e-6);
                Assert.Equal(velocity.Y, jacobian[n + j], 1e-6);
                Assert.Equal(velocity.Z, jacobian[2 * n + j], 1e-6);
                Assert.Equal(omega.X, jacobian[3 * n + j], 1e-8);
                Assert.Equal(omega.Y, jacobian[4 * n + j], 1e-8);
                Assert.Equal(omega.Z, jacobian[5 * n + j], 1e-8);
            }
        }
    }

    [Fact]
    public void Recursion_and_Jacobian_are_allocation_free()
    {
        var state = new KinematicChain(TestRobots.Lb).CreateState();
        var q = new double[] { 0.1, 0.2, 0.3, 0.4, 0.5 };
        var jacobian = new double[6 * 5];
        state.Update(q);
        state.Jacobian(jacobian);
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 100; i++)
        {
            q[0] += 1e-3;
            state.Update(q);
            state.Jacobian(jacobian);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    // dR/dq Rᵀ is the skew matrix of the angular velocity; read its off-diagonal entries.
    private static Vector3d AngularVelocity(Rotation3d plus, Rotation3d minus, Rotation3d r, double h)
    {
        double D(int row, int col) => (plus.At(row, col) - minus.At(row, col)) / (2 * h);
        double W(int row, int col) => D(row, 0) * r.At(col, 0) + D(row, 1) * r.At(col, 1) + D(row, 2) * r.At(col, 2);
        return new Vector3d(W(2, 1), W(0, 2), W(1, 0));
    }

    private static void AssertClose(Vector3d expected, Vector3d actual, double tolerance) =>
        Assert.True((expected - actual).Length <= tolerance, $"expected {expected}, found {actual}");
}
