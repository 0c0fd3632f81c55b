using RobotControl.Analysis.Sweep;
using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Tests.Sweep;

/// <summary>
/// Velocity, force and manipulability at configurations worked out by hand from the DH tables (docs/robots.md). With the
/// shoulder pitch (and LB roll) at 0, both arms lie in the base x-y plane: the upper arm along +x (length L1), the
/// forearm at angle phi_e (elbow) from it, so the tip is p = (L1 + L2 cos phi_e, L2 sin phi_e, 0). Joint axes: yaw
/// z = (0, 0, 1) at the origin, pitch (0, -1, 0) at the origin, LB roll (1, 0, 0) at the origin, elbow (0, 0, 1) at
/// (L1, 0, 0). Columns z × (p − o): yaw (−py, px, 0), pitch (0, 0, px), roll (0, 0, py), elbow (−L2 sin, L2 cos, 0).
/// </summary>
public sealed class HandCheckedConfigurationTests
{
    private const double Deg = Math.PI / 180;
    private const double CrbL1 = 68.58;
    private const double CrbL2 = 96.393;
    private const double LbL1 = 87.57;
    private const double LbL2 = 86.59;

    // Drive figures by hand: eta^n tau eta_m tau_m T_stall (mNm) and omega_noload / (tau tau_m) (rpm -> rad/s).
    private static readonly double CrbShoulderTorque = 0.95 * 0.95 * 2.5 * 0.60 * 256 * 8.99;
    private static readonly double CrbElbowTorque = 0.95 * 0.95 * 1.6 * 0.55 * 1024 * 0.551;
    private static readonly double CrbShoulderSpeed = 27400 / (2.5 * 256) * 2 * Math.PI / 60;
    private static readonly double CrbElbowSpeed = 37300 / (1.6 * 1024) * 2 * Math.PI / 60;
    private static readonly double LbShoulderTorque = 0.95 * 0.95 * (30.0 / 14) * 0.60 * 256 * 8.99;
    private static readonly double LbRollTorque = Math.Pow(0.95, 4) * (30.0 / 14) * 0.60 * 256 * 8.99;
    private static readonly double LbElbowTorque = 0.95 * 0.95 * 1.5 * 0.55 * 1024 * 0.551;
    private static readonly double LbShoulderSpeed = 27400 / ((30.0 / 14) * 256) * 2 * Math.PI / 60;
    private static readonly double LbElbowSpeed = 37300 / (1.5 * 1024) * 2 * Math.PI / 60;

    [Fact]
    public void Crb_arm_straight_out()
    {
        var r = PointOf(TestRobots.Crb, yawDeg: 0, elbowDeg: 0, couplingAware: true);
        var reach = CrbL1 + CrbL2;

        AssertPosition(r, reach, 0);
        Assert.Equal(0, r.Reference.Velocity[0][0], 9);
        Assert.Equal((reach * CrbShoulderSpeed) + (CrbL2 * CrbElbowSpeed), r.Reference.Velocity[1][0], 9);
        Assert.Equal(reach * CrbShoulderSpeed, r.Reference.Velocity[2][0], 9);
        Assert.Equal(30.0, r.Reference.Force[0][0]);
        Assert.Equal(Grid(Math.Min(CrbShoulderTorque / reach, CrbElbowTorque / CrbL2)), r.Reference.Force[1][0]);
        Assert.Equal(4.6, r.Reference.Force[1][0]);
        Assert.Equal(Grid(CrbShoulderTorque / reach), r.Reference.Force[2][0]);
        Assert.Equal(0, r.Manipulability[0], 6);

        // Coupling-aware: both sun-gear motors share the pitch torque (tau_pitch = tau_1 - tau_2), so Fz doubles (capped).
        Assert.Equal(Math.Min(30, Grid(2 * CrbShoulderTorque / reach)), r.CouplingAware!.Force[2][0]);
        Assert.Equal(reach * CrbShoulderSpeed, r.CouplingAware.Velocity[2][0], 9);
    }

    [Fact]
    public void Crb_elbow_at_its_limit()
    {
        var e = 105 * Deg;
        var r = PointOf(TestRobots.Crb, yawDeg: 0, elbowDeg: 105, couplingAware: false);
        var px = CrbL1 + (CrbL2 * Math.Cos(e));
        var py = CrbL2 * Math.Sin(e);

        AssertPosition(r, px, py);
        Assert.Equal((py * CrbShoulderSpeed) + (CrbL2 * Math.Sin(e) * CrbElbowSpeed), r.Reference.Velocity[0][0], 9);
        Assert.Equal((Math.Abs(px) * CrbShoulderSpeed) + (CrbL2 * Math.Abs(Math.Cos(e)) * CrbElbowSpeed), r.Reference.Velocity[1][0], 9);
        Assert.Equal(Math.Abs(px) * CrbShoulderSpeed, r.Reference.Velocity[2][0], 9);
        Assert.Equal(Grid(Math.Min(CrbShoulderTorque / py, CrbElbowTorque / (CrbL2 * Math.Sin(e)))), r.Reference.Force[0][0]);
        Assert.Equal(Grid(Math.Min(CrbShoulderTorque / Math.Abs(px), CrbElbowTorque / (CrbL2 * Math.Abs(Math.Cos(e))))), r.Reference.Force[1][0]);
        Assert.Equal(Math.Min(30, Grid(CrbShoulderTorque / Math.Abs(px))), r.Reference.Force[2][0]);

        // 3 x 3 Jacobian: w = |det J| = |px| · L1 · L2 · sin(phi_e).
        Assert.Equal(Math.Abs(px) * CrbL1 * CrbL2 * Math.Sin(e), r.Manipulability[0], 6);
    }

    [Fact]
    public void Lb_arm_straight_out()
    {
        var r = PointOf(TestRobots.Lb, yawDeg: 0, elbowDeg: 0, couplingAware: false);
        var reach = LbL1 + LbL2;

        AssertPosition(r, reach, 0);
        Assert.Equal(0, r.Reference.Velocity[0][0], 9);
        Assert.Equal((reach * LbShoulderSpeed) + (LbL2 * LbElbowSpeed), r.Reference.Velocity[1][0], 9);
        Assert.Equal(reach * LbShoulderSpeed, r.Reference.Velocity[2][0], 9);
        Assert.Equal(30.0, r.Reference.Force[0][0]);
        Assert.Equal(Grid(Math.Min(LbShoulderTorque / reach, LbElbowTorque / LbL2)), r.Reference.Force[1][0]);
        Assert.Equal(Math.Min(30, Grid(LbShoulderTorque / reach)), r.Reference.Force[2][0]);
    }

    [Fact]
    public void Lb_elbow_at_its_limit()
    {
        var e = 150 * Deg;
        var r = PointOf(TestRobots.Lb, yawDeg: 0, elbowDeg: 150, couplingAware: false);
        var px = LbL1 + (LbL2 * Math.Cos(e));
        var py = LbL2 * Math.Sin(e);

        AssertPosition(r, px, py);
        Assert.Equal((py * LbShoulderSpeed) + (LbL2 * Math.Sin(e) * LbElbowSpeed), r.Reference.Velocity[0][0], 9);
        Assert.Equal((Math.Abs(px) * LbShoulderSpeed) + (LbL2 * Math.Abs(Math.Cos(e)) * LbElbowSpeed), r.Reference.Velocity[1][0], 9);
        Assert.Equal((Math.Abs(px) * LbShoulderSpeed) + (py * LbShoulderSpeed), r.Reference.Velocity[2][0], 9);
        Assert.Equal(Grid(Math.Min(LbShoulderTorque / py, LbElbowTorque / (LbL2 * Math.Sin(e)))), r.Reference.Force[0][0]);
        Assert.Equal(Grid(Math.Min(LbShoulderTorque / Math.Abs(px), LbElbowTorque / (LbL2 * Math.Abs(Math.Cos(e))))), r.Reference.Force[1][0]);
        Assert.Equal(Math.Min(30, Grid(Math.Min(LbShoulderTorque / Math.Abs(px), LbRollTorque / py))), r.Reference.Force[2][0]);
    }

    [Fact]
    public void The_default_sweep_holds_the_hand_checked_point()
    {
        var robot = TestRobots.Crb;
        var report = CapabilityAnalyzer.Run(robot, new AnalysisOptions { Workspace = false });
        var single = PointOf(robot, yawDeg: 0, elbowDeg: 105, couplingAware: false);
        var index = (90 * report.Sweep.YCount) + 105; // yaw -90 + 90 = 0, elbow 0 + 105

        Assert.Equal(136 * 106, report.Sweep.Count);
        Assert.Equal(single.Reference.Force[0][0], report.Sweep.Reference.Force[0][index]);
        Assert.Equal(single.Reference.Velocity[1][0], report.Sweep.Reference.Velocity[1][index], 9);
    }

    private static SweepResult PointOf(RobotDefinition robot, double yawDeg, double elbowDeg, bool couplingAware)
    {
        var yaw = robot.IndexOfJoint("shoulder_yaw");
        var elbow = robot.IndexOfJoint("elbow");
        var spec = new SweepSpecification(
            yaw, yawDeg * Deg, yawDeg * Deg, elbow, elbowDeg * Deg, elbowDeg * Deg, Deg, new double[robot.JointCount], robot.PositionJoints);
        return CapabilityAnalyzer.Run(robot, new AnalysisOptions { Sweep = spec, Workspace = false, CouplingAware = couplingAware }).Sweep;
    }

    private static void AssertPosition(SweepResult r, double x, double y)
    {
        Assert.Equal(1, r.Count);
        Assert.Equal(x, r.Position[0][0], 9);
        Assert.Equal(y, r.Position[1][0], 9);
        Assert.Equal(0, r.Position[2][0], 9);
    }

    // The reference search's grid: the bound quantised down to 0.1 N (none of these bounds lies on a grid point).
    private static double Grid(double bound) => Math.Min(30, Math.Floor(bound * 10) / 10);
}
