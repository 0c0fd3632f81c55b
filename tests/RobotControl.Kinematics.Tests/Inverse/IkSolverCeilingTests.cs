using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>The iteration ceiling is hard: no solve reports more work than its budget, and one that meets it is flagged.</summary>
public sealed class IkSolverCeilingTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void A_budget_of_N_iterations_is_never_exceeded(string file)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var axes = chain.JointCount >= 5 ? OrientationAxes.All : OrientationAxes.Z;
        var targets = Targets(chain, axes).ToList();
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];
        var hitCeiling = 0;
        foreach (var budget in new[] { 1, 2, 3, 5, 8, 13, 31, 60, 120, 200 })
        {
            var solver = new IkSolver(chain, new IkOptions { MaxIterations = budget });
            foreach (var target in targets)
            {
                var result = solver.Solve(target, seed, q);
                Assert.InRange(result.Iterations, 0, budget);
                if (result.AtCeiling)
                {
                    hitCeiling++;
                    Assert.Equal(budget, result.Iterations);
                    Assert.False(result.Reached);
                }

                Assert.True(chain.WithinLimits(q));
            }
        }

        // Small budgets cut reachable solves short, so the flag was exercised, not only the bound.
        Assert.True(hitCeiling > 0);
    }

    [Fact]
    public void At_the_ceiling_the_answer_is_the_best_pose_found_and_flagged()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var made = new[] { -1.5, -1.4, 1.2, 0.2, 0.9 };
        var target = IkTestData.TargetOf(chain, made, OrientationAxes.All);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];
        var state = chain.CreateState();
        state.Update(seed);
        var startError = (state.ToolPosition - target.Position).Length;

        var cut = new IkSolver(chain, new IkOptions { MaxIterations = 3 }).Solve(target, seed, q);

        Assert.True(cut.AtCeiling, cut.ToString());
        Assert.Equal(IkStatus.Unreachable, cut.Status);
        Assert.Equal(3, cut.Iterations);
        state.Update(q);
        Assert.Equal((state.ToolPosition - target.Position).Length, cut.PositionErrorMm, 9);
        Assert.True(cut.PositionErrorMm < startError, $"best found {cut.PositionErrorMm} mm, start {startError} mm");

        var full = new IkSolver(chain).Solve(target, seed, q);
        Assert.True(full.Reached);
        Assert.False(full.AtCeiling);
    }

    [Fact]
    public void A_target_out_of_reach_that_stalls_everywhere_before_the_ceiling_is_not_flagged()
    {
        var chain = new KinematicChain(TestRobots.Crb);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];

        var result = new IkSolver(chain, new IkOptions { MaxIterations = 100_000, MaxRestarts = 2 })
            .Solve(IkTarget.PositionOnly(new Vector3d(1000, 0, 0)), seed, q);

        Assert.Equal(IkStatus.Unreachable, result.Status);
        Assert.True(result.Iterations < 100_000);
        Assert.False(result.AtCeiling);
    }

    private static IEnumerable<IkTarget> Targets(KinematicChain chain, OrientationAxes axes)
    {
        var random = new Random(34);
        for (var s = 0; s < 150; s++)
        {
            yield return IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), axes);
        }

        // Out of reach: the budget is spent on restarts and the final polish.
        for (var s = 0; s < 10; s++)
        {
            var direction = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5);
            yield return new IkTarget(direction * (2000 / direction.Length), Rotation3d.Identity, axes);
        }
    }
}
