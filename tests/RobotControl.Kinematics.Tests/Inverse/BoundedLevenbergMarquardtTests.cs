using RobotControl.Definitions.Model;
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

    private static (BoundedLevenbergMarquardt.Outcome Outcome, double[] Q, int Budget) Run(KinematicChain chain, double[] start, double targetAngle, int budget, int maxSteps) =>
        Run(chain, start, new Vector3d(150 * Math.Cos(targetAngle), 150 * Math.Sin(targetAngle), 0), budget, maxSteps);

    private static (BoundedLevenbergMarquardt.Outcome Outcome, double[] Q, int Budget) Run(KinematicChain chain, double[] start, Vector3d target, int budget, int maxSteps)
    {
        var problem = new IkProblem(chain, new IkOptions { PositionToleranceMm = 1e-9 });
        problem.SetTarget(IkTarget.PositionOnly(target));
        var q = (double[])start.Clone();
        var cost = problem.Evaluate(q);
        var outcome = new BoundedLevenbergMarquardt(chain).Run(problem, q, ref cost, ref budget, maxSteps, 0);
        Assert.Equal(problem.Evaluate(q), cost);
        return (outcome, q, budget);
    }

    [Fact]
    public void No_budget_or_no_steps_allowed_leaves_the_joints_untouched()
    {
        var (outcome, q, budget) = Run(PlanarArm(-0.5, 0.5), [0, 0], 0.3, budget: 0, maxSteps: 10);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.OutOfBudget, outcome);
        Assert.Equal([0.0, 0.0], q);
        Assert.Equal(0, budget);

        (outcome, q, budget) = Run(PlanarArm(-0.5, 0.5), [0, 0], 0.3, budget: 10, maxSteps: 0);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.OutOfBudget, outcome);
        Assert.Equal([0.0, 0.0], q);
        Assert.Equal(10, budget);
    }

    [Fact]
    public void Each_trial_step_costs_one_unit_of_budget_and_a_run_stops_at_its_step_limit()
    {
        // The target is 2.5 rad round: more than three steps of at most 1 rad each.
        var (outcome, q, budget) = Run(PlanarArm(), [0, 0], 2.5, budget: 100, maxSteps: 3);
        Assert.Equal(BoundedLevenbergMarquardt.Outcome.OutOfBudget, outcome);
        Assert.Equal(97, budget);
        Assert.InRange(q[0], 0.5, 3.0 + 1e-12);
    }

    [Fact]
    public void A_step_turns_no_joint_by_more_than_1_rad()
    {
        // One 150 mm link about z, target (0, 400): r = (150, -400), J = (0, 150), so the Gauss-Newton step is
        // 400 / 150 ≈ 2.67 rad (a little less with the damping). It is scaled down to 1 rad, which lowers the
        // distance from 427 mm to 286 mm, so it is taken.
        var link = new KinematicChain([new DhRow(0, 150, 0, 0, 0)], [new JointDefinition("turn", "q0", -Math.PI, Math.PI, "test")]);
        var (_, q, budget) = Run(link, [0], new Vector3d(0, 400, 0), budget: 100, maxSteps: 1);
        Assert.Equal(99, budget);
        Assert.Equal(1.0, q[0], 1e-9);
    }

    [Fact]
    public void A_joint_pinned_at_a_bound_keeps_its_value_while_the_others_move()
    {
        // Joint 1 (within ±0.01 rad) sits on its max and the target lies beyond it: it stays there exactly.
        var (_, q, _) = Run(PlanarArm(), [0, 0.01], 0.5, budget: 100, maxSteps: 1);
        Assert.Equal(0.01, q[1]);
        Assert.True(q[0] > 0.05, $"joint 0 should have moved toward the target, at {q[0]}");
    }
}
