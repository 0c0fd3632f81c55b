using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>What a solve reports, checked by forward kinematics of the joints it returns, however small its budget.</summary>
public sealed class IkSolverResultTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void The_result_describes_the_returned_joints_for_any_budget(string file)
    {
        var chain = new KinematicChain(TestRobots.ByFile(file));
        var state = chain.CreateState();
        var random = new Random(29);
        var n = chain.JointCount;
        var solution = new double[n];
        for (var sample = 0; sample < 60; sample++)
        {
            var options = new IkOptions { MaxIterations = 1 + random.Next(12), MaxRestarts = random.Next(3), WorkspaceStiffnessNPerMm = 0.2 };
            var solver = new IkSolver(chain, options);
            var reachable = IkTestData.RandomJoints(chain, random);
            state.Update(reachable);
            // Half the targets are pushed out of reach, all ask for the tool's z axis.
            var position = sample % 2 == 0 ? state.ToolPosition : state.ToolPosition * 3;
            var target = new IkTarget(position, state.ToolRotation, OrientationAxes.Z);
            var seed = IkTestData.RandomJoints(chain, random);
            var result = solver.Solve(target, seed, solution);

            state.Update(solution);
            var offset = state.ToolPosition - target.Position;
            Assert.True((result.ReachedPosition - state.ToolPosition).Length <= 1e-9, $"sample {sample}: reported {result.ReachedPosition}, FK {state.ToolPosition}");
            Assert.Equal(offset.Length, result.PositionErrorMm, 1e-9);
            Assert.Equal(IkTestData.Angle(state.ToolRotation.Z, target.Rotation.Z), result.OrientationErrorRad, 1e-9);
            Assert.InRange(result.Iterations, 1, options.MaxIterations);
            var expectedForce = result.Reached ? Vector3d.Zero : offset * 0.2;
            Assert.True((result.WorkspaceForce - expectedForce).Length <= 1e-9, $"sample {sample}: force {result.WorkspaceForce}, expected {expectedForce}");
        }
    }

    [Fact]
    public void Restarts_cost_iterations_and_none_allowed_means_one_run()
    {
        // An unreachable target: every run stalls at the boundary of the workspace, and each restart spends budget.
        var chain = new KinematicChain(TestRobots.Lb);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var solution = new double[chain.JointCount];
        var target = new IkTarget(new Vector3d(300, -250, 100), Rotation3d.AboutY(1), OrientationAxes.All);
        var none = new IkSolver(chain, new IkOptions { MaxRestarts = 0 }).Solve(target, seed, solution);
        var eight = new IkSolver(chain, new IkOptions { MaxRestarts = 8 }).Solve(target, seed, solution);
        Assert.False(none.Reached);
        Assert.False(eight.Reached);
        Assert.True(none.Iterations < eight.Iterations, $"no restarts: {none.Iterations} iterations, eight: {eight.Iterations}");
    }
}
