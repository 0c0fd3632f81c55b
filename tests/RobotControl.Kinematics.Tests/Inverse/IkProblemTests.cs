using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>The least-squares form the solver descends, checked against finite differences and hand-derived values.</summary>
public sealed class IkProblemTests
{
    [Fact]
    public void A_far_target_is_pulled_in_along_its_direction_to_the_far_limit()
    {
        var problem = new IkProblem(new KinematicChain(TestRobots.Crb), new IkOptions());
        Assert.True(problem.SetTarget(IkTarget.PositionOnly(new Vector3d(3e6, 0, -4e6))));
        Assert.Equal(new Vector3d(0.6e6, 0, -0.8e6), problem.TargetPosition, (a, b) => (a - b).Length < 1e-6);
        Assert.True(problem.SetTarget(IkTarget.PositionOnly(new Vector3d(3e5, 0, -4e5))));
        Assert.Equal(new Vector3d(3e5, 0, -4e5), problem.TargetPosition);
    }

    [Fact]
    public void A_target_too_far_for_its_length_to_be_a_double_is_still_pulled_in_along_its_direction()
    {
        // |p| = √2 · MaxValue overflows; the direction (1, 1, 0) / √2 does not.
        var problem = new IkProblem(new KinematicChain(TestRobots.Crb), new IkOptions());
        Assert.True(problem.SetTarget(IkTarget.PositionOnly(new Vector3d(double.MaxValue, double.MaxValue, 0))));
        var expected = new Vector3d(1, 1, 0) * (IkProblem.FarTargetMm / Math.Sqrt(2));
        Assert.True((problem.TargetPosition - expected).Length < 1e-6, $"pulled in to {problem.TargetPosition}");
        Assert.True(problem.SetTarget(IkTarget.PositionOnly(new Vector3d(1, double.MaxValue, 0))));
        Assert.True((problem.TargetPosition - new Vector3d(0, IkProblem.FarTargetMm, 0)).Length < 1e-6, $"pulled in to {problem.TargetPosition}");
    }

    [Fact]
    public void Safe_length_is_the_euclidean_length_without_overflow()
    {
        Assert.Equal(5, IkProblem.SafeLength(new Vector3d(0, 5, 0)));
        Assert.Equal(5, IkProblem.SafeLength(new Vector3d(0, 0, -5)));
        Assert.Equal(13, IkProblem.SafeLength(new Vector3d(3, 4, 12)), 14);
        Assert.Equal(5e200, IkProblem.SafeLength(new Vector3d(3e200, -4e200, 0)), 1e188);
        Assert.Equal(0, IkProblem.SafeLength(Vector3d.Zero));
        Assert.Equal(double.PositiveInfinity, IkProblem.SafeLength(new Vector3d(double.NegativeInfinity, 1, 0)));
    }

    [Fact]
    public void The_largest_axis_angle_is_the_worst_selected_axis()
    {
        // CRB-1.0 with only the yaw turned: the tool frame is the base frame turned by the yaw about z. A target
        // turned 0.5 rad about z puts the x axis 0.5 - yaw off and leaves z on target.
        var problem = new IkProblem(new KinematicChain(TestRobots.Crb), new IkOptions());
        Assert.True(problem.SetTarget(new IkTarget(Vector3d.Zero, Rotation3d.AboutZ(0.5), OrientationAxes.X | OrientationAxes.Z)));
        problem.Evaluate([0.2, 0, 0, 0]);
        var state = new KinematicChain(TestRobots.Crb).CreateState();
        state.Update([0.2, 0, 0, 0]);
        var expected = Math.Max(
            IkTestData.Angle(state.ToolRotation.X, Rotation3d.AboutZ(0.5).X),
            IkTestData.Angle(state.ToolRotation.Z, Rotation3d.AboutZ(0.5).Z));
        Assert.True(expected > 0.1, $"the test pose should be off target (largest angle {expected})");
        Assert.Equal(expected, problem.LargestAxisAngle(), 12);
    }

    [Fact]
    public void Weighted_residual_Jacobian_and_normal_equations_match_finite_differences()
    {
        // Cost = Σ r² with r = (√wp (p - pd), √wo (Rh_k - Rd_k)): J = dr/dq, normal = JᵀJ, Jᵀr = ½ dCost/dq.
        var chain = new KinematicChain(TestRobots.Lb);
        var options = new IkOptions { PositionWeight = 4, OrientationWeight = 9 };
        var problem = new IkProblem(chain, options);
        var rd = Rotation3d.FromRollPitchYaw(0.3, -0.2, 0.9);
        Assert.True(problem.SetTarget(new IkTarget(new Vector3d(40, -30, 60), rd, OrientationAxes.X | OrientationAxes.Z)));
        double[] q = [0.1, -0.5, 0.4, 0.8, -0.3];
        var n = chain.JointCount;
        var m = problem.ResidualCount;
        Assert.Equal(9, m);
        var jacobian = new double[m * n];
        var normal = new double[n * n];
        var jtr = new double[n];
        var cost = problem.Evaluate(q);
        problem.NormalEquations(jacobian, normal, jtr);

        var state = chain.CreateState();
        double[] Residual(double[] at)
        {
            state.Update(at);
            var dp = (state.ToolPosition - new Vector3d(40, -30, 60)) * 2;
            var dx = (state.ToolRotation.X - rd.X) * 3;
            var dz = (state.ToolRotation.Z - rd.Z) * 3;
            return [dp.X, dp.Y, dp.Z, dx.X, dx.Y, dx.Z, dz.X, dz.Y, dz.Z];
        }

        Assert.Equal(Residual(q).Sum(r => r * r), cost, 1e-9 * cost);
        var numeric = new double[m, n];
        for (var i = 0; i < n; i++)
        {
            const double h = 1e-6;
            var (plus, minus) = IkTestData.Nudged(q, i, h);
            var rp = Residual(plus);
            var rm = Residual(minus);
            for (var r = 0; r < m; r++)
            {
                numeric[r, i] = (rp[r] - rm[r]) / (2 * h);
                Assert.True(Math.Abs(numeric[r, i] - jacobian[(r * n) + i]) <= 1e-5 * (1 + Math.Abs(numeric[r, i])), $"J[{r}, {i}]");
            }

            problem.Evaluate(plus);
            var costPlus = problem.CurrentCost();
            problem.Evaluate(minus);
            var slope = (costPlus - problem.CurrentCost()) / (2 * h);
            Assert.True(Math.Abs((0.5 * slope) - jtr[i]) <= 1e-5 * (1 + Math.Abs(slope)), $"Jᵀr[{i}]: {jtr[i]} vs {0.5 * slope}");
        }

        for (var i = 0; i < n; i++)
        {
            for (var j = 0; j < n; j++)
            {
                var expected = 0.0;
                for (var r = 0; r < m; r++)
                {
                    expected += numeric[r, i] * numeric[r, j];
                }

                Assert.True(Math.Abs(expected - normal[(i * n) + j]) <= 1e-5 * (1 + Math.Abs(expected)), $"(JᵀJ)[{i}, {j}]");
            }
        }
    }
}
