using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class IkSolverRobustnessTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void Answers_stay_within_limits_and_finite_for_any_target_and_seed(string file)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var solver = new IkSolver(chain);
        var random = new Random(21);
        var n = chain.JointCount;
        var seed = new double[n];
        var q = new double[n];
        foreach (var target in Targets(chain, random))
        {
            for (var i = 0; i < n; i++)
            {
                // Seeds far outside the limits, and sometimes not numbers at all.
                seed[i] = random.Next(6) switch
                {
                    0 => double.NaN,
                    1 => double.PositiveInfinity,
                    _ => (random.NextDouble() - 0.5) * 20,
                };
            }

            var result = solver.Solve(target, seed, q);
            Assert.True(chain.WithinLimits(q), $"outside limits for {target}");
            Assert.All(q, v => Assert.True(double.IsFinite(v)));
            AssertNoNaN(result);
            Assert.True(result.WorkspaceForce.IsFinite);
        }
    }

    [Fact]
    public void A_target_with_NaN_or_infinity_returns_the_seed_clamped_and_no_force()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain);
        double[] seed = [-3, 0.1, double.NaN, 2, 0.5];
        var q = new double[5];
        IkTarget[] invalid =
        [
            IkTarget.PositionOnly(new Vector3d(double.NaN, 0, 0)),
            IkTarget.PositionOnly(new Vector3d(0, double.PositiveInfinity, 0)),
            new(new Vector3d(50, 0, 0), new Rotation3d(Vector3d.UnitX, new Vector3d(0, double.NaN, 0), Vector3d.UnitZ), OrientationAxes.Y),
        ];
        foreach (var target in invalid)
        {
            var result = solver.Solve(target, seed, q);
            Assert.Equal(IkStatus.InvalidTarget, result.Status);
            Assert.Equal(Vector3d.Zero, result.WorkspaceForce);
            AssertNoNaN(result);
            Assert.Equal([chain.MinRad[0], 0.1, 0.0, 2.0, 0.5], q, new ToleranceComparer(1e-15));
        }
    }

    [Fact]
    public void A_NaN_in_an_axis_that_is_not_selected_is_ignored()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain);
        var reachable = IkTestData.TargetOf(chain, [-0.3, -0.5, 0.2, 1.0, 0.4], OrientationAxes.Z);
        var target = reachable with
        {
            Rotation = new Rotation3d(new Vector3d(double.NaN, 0, 0), Vector3d.UnitY, reachable.Rotation.Z),
        };
        var seed = new double[5];
        chain.MidRange(seed);
        var q = new double[5];
        Assert.Equal(IkStatus.Reached, solver.Solve(target, seed, q).Status);
        IkTestData.AssertReaches(chain, target, q);
    }

    [Fact]
    public void Spans_shorter_than_the_joint_count_are_rejected()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        var solver = new IkSolver(chain);
        var target = IkTarget.PositionOnly(new Vector3d(50, -50, -50));
        Assert.Throws<ArgumentException>(() => solver.Solve(target, new double[3], new double[4]));
        Assert.Throws<ArgumentException>(() => solver.Solve(target, new double[4], new double[3]));
    }

    [Fact]
    public void Invalid_options_and_empty_joint_ranges_are_rejected_at_construction()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        Assert.Throws<ArgumentOutOfRangeException>(() => new IkSolver(chain, new IkOptions { PositionToleranceMm = 0 }));
        Assert.Throws<ArgumentOutOfRangeException>(() => new IkSolver(chain, new IkOptions { OrientationWeight = double.NaN }));
        Assert.Throws<ArgumentOutOfRangeException>(() => new IkSolver(chain, new IkOptions { MaxIterations = 0 }));
        var rows = chain.Rows;
        Definitions.Model.JointDefinition[] joints = [.. chain.Joints];
        joints[1] = joints[1] with { MinRad = 1, MaxRad = 0 };
        Assert.Throws<ArgumentException>(() => new IkSolver(new KinematicChain(rows, joints)));
    }

    [Fact]
    public void Solving_allocates_nothing()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain);
        var targets = Targets(chain, new Random(8)).ToArray();
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];
        foreach (var target in targets)
        {
            solver.Solve(target, seed, q);
        }

        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var round = 0; round < 3; round++)
        {
            foreach (var target in targets)
            {
                solver.Solve(target, seed, q);
                solver.Solve(target, q, q);
            }
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    /// <summary>Reachable, unreachable, absurdly far and degenerate targets.</summary>
    private static IEnumerable<IkTarget> Targets(KinematicChain chain, Random random)
    {
        OrientationAxes[] masks = [OrientationAxes.None, OrientationAxes.Z, OrientationAxes.All, OrientationAxes.X | OrientationAxes.Y];
        for (var s = 0; s < 40; s++)
        {
            var axes = masks[s % masks.Length];
            yield return IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), axes);
            var far = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5) * 1000;
            var rotation = Rotation3d.FromRollPitchYaw(random.NextDouble() * 6, random.NextDouble() * 3, random.NextDouble() * 6);
            yield return new IkTarget(far, rotation, axes);
        }

        yield return IkTarget.PositionOnly(new Vector3d(1e300, -1e300, 1e300));
        yield return IkTarget.PositionOnly(new Vector3d(double.MaxValue, double.MinValue, 0));
        yield return IkTarget.PositionOnly(Vector3d.Zero);
        yield return new IkTarget(new Vector3d(80, -60, -40), new Rotation3d(Vector3d.Zero, Vector3d.Zero, Vector3d.Zero), OrientationAxes.All);
        yield return new IkTarget(new Vector3d(80, -60, -40), new Rotation3d(Vector3d.UnitX * 1e300, Vector3d.UnitY * 1e-300, Vector3d.UnitZ), OrientationAxes.All);
        yield return IkTarget.PositionOnly(new Vector3d(double.NaN, 0, 0));
    }

    private static void AssertNoNaN(IkResult result)
    {
        Assert.False(double.IsNaN(result.PositionErrorMm));
        Assert.False(double.IsNaN(result.OrientationErrorRad));
        Assert.True(result.ReachedPosition.IsFinite);
        Assert.True(result.WorkspaceForce.IsFinite);
    }

    private sealed class ToleranceComparer(double tolerance) : IEqualityComparer<double>
    {
        public bool Equals(double x, double y) => Math.Abs(x - y) <= tolerance;

        public int GetHashCode(double obj) => 0;
    }
}
