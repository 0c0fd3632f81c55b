using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class IkSolverUnreachableTests
{
    [Theory]
    [InlineData("lb-1.0.json")]
    [InlineData("crb-1.0.json")]
    public void An_unreachable_point_gives_the_nearest_reachable_point_and_a_spring_back_to_it(string file)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var options = new IkOptions();
        var solver = new IkSolver(chain, options);
        var grid = DenseWorkspace(chain, steps: 16);
        var random = new Random(4);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];
        var checkedTargets = 0;
        for (var s = 0; s < 6; s++)
        {
            // Points outside the reach sphere in random directions, and a few inside it behind the joint limits.
            var direction = new Vector3d(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.5).Normalized();
            var target = IkTarget.PositionOnly(direction * (s < 4 ? 250 + (100 * s) : 60));
            var nearestOnGrid = grid.Min(p => Vector3d.Distance(p, target.Position));
            if (nearestOnGrid < 1)
            {
                continue;
            }

            var result = solver.Solve(target, seed, q);
            if (s >= 4 && result.Reached)
            {
                // Inside the reach sphere the coarse grid may miss a reachable pocket: then it must really be reached.
                IkTestData.AssertReaches(chain, target, q);
                continue;
            }

            checkedTargets++;
            Assert.Equal(IkStatus.Unreachable, result.Status);
            Assert.True(chain.WithinLimits(q));
            var state = chain.CreateState();
            state.Update(q);
            var reached = state.ToolPosition;
            Assert.Equal(reached, result.ReachedPosition);
            var distance = Vector3d.Distance(reached, target.Position);
            Assert.Equal(distance, result.PositionErrorMm, 9);

            // No dense-grid pose comes closer, and no small in-limit perturbation improves it by more than a tenth of the
            // position tolerance (Gauss-Newton converges only linearly at a large residual; measured gaps ~1e-5 mm).
            Assert.True(distance <= nearestOnGrid + 1e-9, $"{distance} mm vs grid {nearestOnGrid} mm");
            var nearby = BestNearby(chain, q, target.Position, random);
            Assert.True(distance <= nearby + (0.1 * IkTestData.PositionToleranceMm), $"target {target.Position}: {distance} mm, a nearby pose {nearby} mm, {result.Iterations} iterations");

            // F = k_s (Ph - Pd): from the demanded point back toward the reachable one.
            var expected = (reached - target.Position) * options.WorkspaceStiffnessNPerMm;
            Assert.Equal(expected.X, result.WorkspaceForce.X, 12);
            Assert.Equal(expected.Y, result.WorkspaceForce.Y, 12);
            Assert.Equal(expected.Z, result.WorkspaceForce.Z, 12);
            Assert.True(Vector3d.Dot(result.WorkspaceForce, reached - target.Position) > 0);
        }

        Assert.InRange(checkedTargets, 4, 6);
    }

    [Fact]
    public void A_point_far_out_stretches_the_arm_toward_it()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var solver = new IkSolver(chain);
        var grid = DenseWorkspace(chain, steps: 16);
        var reach = grid.Max(p => p.Length);
        var state = chain.CreateState();

        // A direction the arm can point in: where a pose within the limits puts the tool.
        state.Update([-0.4, -0.6, 0.3, 0.0, 0.0]);
        var direction = state.ToolPosition.Normalized();
        var target = IkTarget.PositionOnly(direction * 5000);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var q = new double[chain.JointCount];
        var result = solver.Solve(target, seed, q);
        Assert.Equal(IkStatus.Unreachable, result.Status);
        Assert.True(result.ReachedPosition.Length >= reach - 1e-6, $"{result.ReachedPosition.Length} mm of {reach} mm reach");
        Assert.True(IkTestData.Angle(result.ReachedPosition, direction) < 1e-4);
        Assert.True(Vector3d.Dot(result.WorkspaceForce, -direction) > 0.05 * (5000 - reach) * 0.999);
    }

    private static List<Vector3d> DenseWorkspace(KinematicChain chain, int steps)
    {
        var state = chain.CreateState();
        var n = chain.JointCount;
        var q = new double[n];
        var points = new List<Vector3d>();
        var index = new int[n];

        // The last joint (tool roll) does not move the tool tip on either robot: hold it at 0.
        var gridJoints = n - 1;
        while (true)
        {
            for (var i = 0; i < gridJoints; i++)
            {
                q[i] = chain.MinRad[i] + ((chain.MaxRad[i] - chain.MinRad[i]) * index[i] / (steps - 1));
            }

            state.Update(q);
            points.Add(state.ToolPosition);
            var k = 0;
            while (k < gridJoints && ++index[k] == steps)
            {
                index[k] = 0;
                k++;
            }

            if (k == gridJoints)
            {
                return points;
            }
        }
    }

    private static double BestNearby(KinematicChain chain, double[] q, Vector3d target, Random random)
    {
        var state = chain.CreateState();
        var trial = new double[q.Length];
        var best = double.PositiveInfinity;
        for (var s = 0; s < 400; s++)
        {
            for (var i = 0; i < q.Length; i++)
            {
                trial[i] = q[i] + ((random.NextDouble() - 0.5) * 1e-3);
            }

            chain.Clamp(trial);
            state.Update(trial);
            best = Math.Min(best, Vector3d.Distance(state.ToolPosition, target));
        }

        return best;
    }
}
