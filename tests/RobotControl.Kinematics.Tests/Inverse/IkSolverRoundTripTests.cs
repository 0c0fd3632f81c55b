using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class IkSolverRoundTripTests
{
    [Theory]
    [InlineData("lb-1.0.json", OrientationAxes.All)]
    [InlineData("lb-1.0.json", OrientationAxes.None)]
    [InlineData("crb-1.0.json", OrientationAxes.Z)]
    [InlineData("crb-1.0.json", OrientationAxes.None)]
    public void Random_reachable_targets_are_reached_from_the_mid_range_seed(string file, OrientationAxes axes)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        RoundTrips(chain, axes, samples: 400, seed: 11);
    }

    [Fact]
    public void A_chain_built_in_code_is_solved_for_full_poses()
    {
        // The default budget is tuned for the two robots; a 6-DOF arm with tight limits has more local minima and is
        // given more restarts and steps.
        var options = new IkOptions { MaxRestarts = 40, MaxIterations = 2000 };
        RoundTrips(IkTestData.Puma(), OrientationAxes.All, samples: 150, seed: 5, options);
    }

    [Fact]
    public void Tracking_from_the_previous_answer_takes_few_iterations()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain);
        var q = new double[chain.JointCount];
        chain.MidRange(q);
        var path = new double[chain.JointCount];
        var worst = 0;
        for (var step = 0; step < 500; step++)
        {
            // A slow joint-space path: tool steps well under 1 mm at 1 kHz.
            var t = step * 1e-3;
            for (var i = 0; i < path.Length; i++)
            {
                var mid = 0.5 * (chain.MinRad[i] + chain.MaxRad[i]);
                path[i] = mid + (0.3 * (chain.MaxRad[i] - chain.MinRad[i]) * Math.Sin((0.7 + i) * t));
            }

            var target = IkTestData.TargetOf(chain, path, OrientationAxes.All);
            var result = solver.Solve(target, q, q);
            Assert.Equal(IkStatus.Reached, result.Status);
            IkTestData.AssertReaches(chain, target, q);
            if (step > 0)
            {
                worst = Math.Max(worst, result.Iterations);
            }
        }

        Assert.InRange(worst, 0, 3);
    }

    [Fact]
    public void The_same_inputs_give_the_same_answer()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var random = new Random(3);
        var target = IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), OrientationAxes.All);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var first = new double[chain.JointCount];
        var second = new double[chain.JointCount];
        var solver = new IkSolver(chain);
        solver.Solve(target, seed, first);
        // Another solve in between must leave nothing behind (the restart generator is reseeded per solve).
        solver.Solve(IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), OrientationAxes.All), seed, second);
        solver.Solve(target, seed, second);
        Assert.Equal(first, second);
    }

    private static void RoundTrips(KinematicChain chain, OrientationAxes axes, int samples, int seed, IkOptions? options = null)
    {
        var solver = new IkSolver(chain, options);
        var random = new Random(seed);
        var start = new double[chain.JointCount];
        chain.MidRange(start);
        var q = new double[chain.JointCount];
        for (var s = 0; s < samples; s++)
        {
            var target = IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, random), axes);
            var result = solver.Solve(target, start, q);
            Assert.Equal(IkStatus.Reached, result.Status);
            Assert.Equal(Geometry.Vector3d.Zero, result.WorkspaceForce);
            Assert.InRange(result.PositionErrorMm, 0, Math.Sqrt(3) * IkTestData.PositionToleranceMm);
            IkTestData.AssertReaches(chain, target, q);
        }
    }
}
