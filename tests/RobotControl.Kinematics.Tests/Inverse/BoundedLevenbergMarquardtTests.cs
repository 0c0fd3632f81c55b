using RobotControl.Hardware.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class BoundedLevenbergMarquardtTests
{
    // A planar two-link arm: joint 0 turns a whole turn (-180..180 deg, as LB-1.0's tool roll), joint 1 barely moves.
    private static KinematicChain PlanarArm(double firstMin = -Math.PI, double firstMax = Math.PI) => new(
        [new DhRow(0, 100, 0, 0, 0), new DhRow(0, 50, 0, 0, 1)],
        [new JointDefinition("turn", "q0", firstMin, firstMax, "test"), new JointDefinition("small", "q1", -0.01, 0.01, "test")]);

    private static (BoundedLevenbergMarquardt.Outcome Outcome, double[] Q) Solve(KinematicChain chain, double[] start, double targetAngle)
    {
        var problem = new IkProblem(chain, new IkOptions());
        problem.SetTarget(new IkTarget(new Vector3d(150 * Math.Cos(targetAngle), 150 * Math.Sin(targetAngle), 0), Rotation3d.Identity, OrientationAxes.None));
        var q = (double[])start.Clone();
        var cost = problem.Evaluate(q);
        var budget = 200;
        var outcome = new BoundedLevenbergMarquardt(chain).Run(problem, q, ref cost, ref budget, 100, 1e-13);
        return (outcome, q);
    }

    [Fact]
    public void A_full_turn_joint_at_its_max_bound_steps_through_the_end_and_reenters_at_the_other()
    {
        // From +180 deg the target lies 0.3 rad further on, i.e. at -180 + 0.3 rad: descent pushes joint 0 outward
        // past its max. A whole-turn joint has no real end there, so it must not be pinned.
        var (outcome, q) = Solve(PlanarArm(), [Math.PI, 0], -Math.PI + 0.3);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.Reached, outcome);
        Assert.Equal(-Math.PI + 0.3, q[0], 0.02);
    }

    [Fact]
    public void A_full_turn_joint_at_its_min_bound_steps_through_the_end_and_reenters_at_the_other()
    {
        var (outcome, q) = Solve(PlanarArm(), [-Math.PI, 0], Math.PI - 0.3);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.Reached, outcome);
        Assert.Equal(Math.PI - 0.3, q[0], 0.02);
    }

    [Fact]
    public void A_bounded_joint_at_its_max_bound_stays_pinned_when_the_target_lies_beyond()
    {
        // Joint 0 (less than a turn) sits at its max with the target beyond it: it is pinned there, never wrapped.
        var (outcome, q) = Solve(PlanarArm(-0.5, 0.5), [0.5, 0], 1.0);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.Stalled, outcome);
        Assert.Equal(0.5, q[0]);
    }
}
