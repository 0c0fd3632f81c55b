using MathNet.Numerics.LinearAlgebra;
using RobotControl.Kinematics.Forward;

namespace RobotControl.Kinematics.Tests.Forward;

public sealed class ManipulabilityTests
{
    public static TheoryData<string> Robots => TestRobots.Names;

    [Theory]
    [MemberData(nameof(Robots))]
    public void Closed_form_matches_MathNet_determinant_of_J_J_transpose(string file)
    {
        var robot = TestRobots.ByFile(file);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var n = chain.JointCount;
        var jacobian = new double[6 * n];
        var q = new double[n];
        var random = new Random(11);
        var positionJoints = robot.PositionJoints.ToArray();
        for (var sample = 0; sample < 200; sample++)
        {
            TestRobots.FillRandomJoints(chain, random, q);

            state.Update(q);
            state.Jacobian(jacobian);
            var jp = Matrix<double>.Build.Dense(3, n, (r, c) => jacobian[r * n + c]);
            var expected = Math.Sqrt(Math.Max(0, (jp * jp.Transpose()).Determinant()));
            var subset = Matrix<double>.Build.Dense(3, positionJoints.Length, (r, c) => jacobian[r * n + positionJoints[c]]);
            var expectedSubset = Math.Sqrt(Math.Max(0, (subset * subset.Transpose()).Determinant()));

            var scale = Math.Max(1, expected);
            Assert.True(Math.Abs(Manipulability.FromJacobian(jacobian, n) - expected) <= 1e-9 * scale);
            Assert.True(Math.Abs(Manipulability.Of(state) - expected) <= 1e-9 * scale);
            Assert.True(Math.Abs(Manipulability.Of(state, positionJoints) - expectedSubset) <= 1e-9 * Math.Max(1, expectedSubset));
            Assert.True(expected > 0);
        }
    }

    [Fact]
    public void Crb_with_a_straight_elbow_is_singular()
    {
        var state = new KinematicChain(TestRobots.Crb).CreateState();
        state.Update([0.3, -0.4, 0, 0.2]);
        Assert.True(Manipulability.Of(state) < 1e-6);
        state.Update([0.3, -0.4, Math.PI / 2, 0.2]);
        Assert.True(Manipulability.Of(state) > 1e3);
    }

    [Fact]
    public void Is_allocation_free()
    {
        var state = new KinematicChain(TestRobots.Lb).CreateState();
        var jacobian = new double[6 * 5];
        int[] joints = [0, 1, 2, 3];
        state.Update([0.1, 0.2, 0.3, 0.4, 0.5]);
        state.Jacobian(jacobian);
        var sum = Manipulability.Of(state) + Manipulability.FromJacobian(jacobian, 5) + Manipulability.Of(state, joints);
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 100; i++)
        {
            sum += Manipulability.Of(state) + Manipulability.FromJacobian(jacobian, 5) + Manipulability.Of(state, joints);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        Assert.True(sum > 0);
    }
}
