using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>The solver's option checks, joint ranges and what it answers for a target it cannot use.</summary>
public sealed class IkSolverSetupTests
{
    private static readonly IkTarget NaNTarget = IkTarget.PositionOnly(new Vector3d(double.NaN, 0, 0));

    private static KinematicChain PlanarArm(JointDefinition first, JointDefinition second) =>
        new([new DhRow(0, 100, 0, 0, 0), new DhRow(0, 50, 0, 0, 1)], [first, second]);

    public static TheoryData<IkOptions> Refused => new()
    {
        new IkOptions { OrientationToleranceRad = 0 },
        new IkOptions { PositionWeight = 0 },
        new IkOptions { WorkspaceStiffnessNPerMm = -1 },
        new IkOptions { WorkspaceStiffnessNPerMm = double.NaN },
        new IkOptions { WorkspaceStiffnessNPerMm = double.PositiveInfinity },
        new IkOptions { MaxRestarts = -1 },
    };

    [Theory]
    [MemberData(nameof(Refused))]
    public void Options_out_of_range_are_refused(IkOptions options) =>
        Assert.Throws<ArgumentOutOfRangeException>(() => new IkSolver(new KinematicChain(TestRobots.Crb), options));

    [Fact]
    public void The_smallest_allowed_options_are_accepted_and_a_null_chain_is_not()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        var solver = new IkSolver(chain, new IkOptions { WorkspaceStiffnessNPerMm = 0, MaxIterations = 1, MaxRestarts = 0 });
        Assert.Equal(1, solver.Options.MaxIterations);
        Assert.Throws<ArgumentNullException>(() => new IkSolver(null!));
    }

    [Fact]
    public void A_joint_with_a_single_allowed_angle_is_held_there()
    {
        var chain = PlanarArm(new JointDefinition("a", "q0", -Math.PI, Math.PI, "test"), new JointDefinition("b", "q1", 0.3, 0.3, "test"));
        var solver = new IkSolver(chain);
        var solution = new double[2];
        var target = IkTarget.PositionOnly(new Vector3d(100 + (50 * Math.Cos(0.3)), 50 * Math.Sin(0.3), 0));
        var result = solver.Solve(target, [0.5, 0.3], solution);
        Assert.True(result.Reached);
        Assert.Equal(0.3, solution[1]);
        Assert.Equal(0, solution[0], 1e-3);
    }

    // A NaN seed entry starts from the middle of the range restarts sample: [min, max], or one turn beside a finite
    // end, or [-π, π] with no end at all. An unusable target returns that start.
    [Theory]
    [InlineData(-1.0, 2.0, 0.5)]
    [InlineData(double.NegativeInfinity, 1.0, 1 - Math.PI)]
    [InlineData(-1.0, double.PositiveInfinity, Math.PI - 1)]
    [InlineData(double.NegativeInfinity, double.PositiveInfinity, 0.0)]
    public void A_NaN_seed_starts_mid_range_even_for_unbounded_joints(double min, double max, double expected)
    {
        var chain = PlanarArm(new JointDefinition("a", "q0", min, max, "test"), new JointDefinition("b", "q1", -1, 1, "test"));
        var solver = new IkSolver(chain);
        var solution = new double[2];
        var result = solver.Solve(NaNTarget, [double.NaN, double.NaN], solution);
        Assert.Equal(IkStatus.InvalidTarget, result.Status);
        Assert.Equal(expected, solution[0], 12);
        Assert.Equal(0, solution[1], 15);
    }

    [Fact]
    public void An_unusable_target_reports_the_position_of_the_returned_joints()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        var solver = new IkSolver(chain);
        var solution = new double[4];
        var state = chain.CreateState();
        double[] q = [0.2, -0.4, 0.8, 0];
        state.Update(q);
        Assert.True(solver.Solve(IkTarget.PositionOnly(state.ToolPosition), q, solution).Reached);

        double[] seed = [-0.5, 0.1, 0.3, 0.2];
        var result = solver.Solve(NaNTarget, seed, solution);
        state.Update(seed);
        Assert.Equal(seed, solution);
        Assert.Equal(state.ToolPosition, result.ReachedPosition, (a, b) => (a - b).Length < 1e-12);
    }

    [Fact]
    public void A_target_beyond_the_range_of_doubles_stretches_the_arm_toward_it_and_reports_the_largest_error()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        var solver = new IkSolver(chain);
        var solution = new double[4];
        var seed = new double[4];
        chain.MidRange(seed);
        var result = solver.Solve(IkTarget.PositionOnly(new Vector3d(double.MaxValue, -double.MaxValue, -double.MaxValue)), seed, solution);
        Assert.Equal(IkStatus.Unreachable, result.Status);
        Assert.Equal(double.MaxValue, result.PositionErrorMm);
        // The tool ends on the reach sphere in the target's direction (1, -1, -1) / √3, as for any far target.
        var direction = result.ReachedPosition / result.ReachedPosition.Length;
        Assert.True((direction - (new Vector3d(1, -1, -1) / Math.Sqrt(3))).Length < 1e-3, $"stretched toward {direction}");
    }

    [Fact]
    public void A_short_solution_span_is_refused_naming_it()
    {
        var solver = new IkSolver(new KinematicChain(TestRobots.Crb));
        var message = Assert.Throws<ArgumentException>(() => solver.Solve(IkTarget.PositionOnly(new Vector3d(50, -50, -50)), new double[4], new double[3])).Message;
        Assert.Contains("solution has room for 3 values; the chain has 4 joints", message, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(1)]
    [InlineData(7)]
    [InlineData(40)]
    [InlineData(100)]
    public void An_unreachable_target_never_takes_more_iterations_than_allowed(int maxIterations)
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain, new IkOptions { MaxIterations = maxIterations, MaxRestarts = 1000 });
        var solution = new double[chain.JointCount];
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var result = solver.Solve(new IkTarget(new Vector3d(400, 300, -200), Rotation3d.AboutX(2), OrientationAxes.All), seed, solution);
        Assert.False(result.Reached);
        Assert.InRange(result.Iterations, 1, maxIterations);
    }
}
