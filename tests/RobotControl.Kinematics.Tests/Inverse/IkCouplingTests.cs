using RobotControl.Kinematics.Coupling;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>IK answers mapped through the shoulder coupling (JointMotorMap) obey docs/robots.md's equations.</summary>
public sealed class IkCouplingTests
{
    [Fact]
    public void LB_shoulder_gears_of_IK_answers_follow_the_coupling_equations()
    {
        var robot = TestRobots.Lb;
        var gears = SolveAndCouple(robot, OrientationAxes.All, out var q);
        Assert.Equal(q[0] + q[1], gears[robot.Actuators.ToList().FindIndex(a => a.Name == "shoulder_1")], 12);
        Assert.Equal(q[0] - q[1], gears[robot.Actuators.ToList().FindIndex(a => a.Name == "shoulder_2")], 12);
        Assert.Equal(q[2] - q[0] - q[1], gears[robot.Actuators.ToList().FindIndex(a => a.Name == "shoulder_3")], 12);
        Assert.Equal(q[3], gears[3], 12);
        Assert.Equal(q[4], gears[4], 12);
    }

    [Fact]
    public void CRB_sun_gears_of_IK_answers_follow_the_coupling_equations()
    {
        var robot = TestRobots.Crb;
        var gears = SolveAndCouple(robot, OrientationAxes.Z, out var q);
        Assert.Equal(q[0] + q[1], gears[0], 12);
        Assert.Equal(q[0] - q[1], gears[1], 12);
        Assert.Equal(q[2], gears[2], 12);
        Assert.Equal(q[3], gears[3], 12);
    }

    private static double[] SolveAndCouple(Definitions.Model.RobotDefinition robot, OrientationAxes axes, out double[] q)
    {
        var chain = new KinematicChain(robot);
        var map = new JointMotorMap(robot);
        var solver = new IkSolver(chain);
        var target = IkTestData.TargetOf(chain, IkTestData.RandomJoints(chain, new Random(12)), axes);
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        q = new double[chain.JointCount];
        Assert.True(solver.Solve(target, seed, q).Reached);
        var gears = new double[map.JointCount];
        map.JointsToActuators(q, gears);
        return gears;
    }
}
