using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>Reachable targets and independent checks for the IK tests.</summary>
internal static class IkTestData
{
    public const double PositionToleranceMm = 0.01;
    public const double OrientationToleranceRad = 1e-5;

    /// <summary>A 6-DOF PUMA-560-like chain (mm) built here, not from a robot file: offsets in a and d on several rows.</summary>
    public static KinematicChain Puma()
    {
        const double deg = Math.PI / 180;
        DhRow[] rows =
        [
            new(90 * deg, 0, 0, 0, 0),
            new(0, 431.8, 0, 0, 1),
            new(-90 * deg, 20.3, 150.05, 0, 2),
            new(90 * deg, 0, 431.8, 0, 3),
            new(-90 * deg, 0, 0, 0, 4),
            new(0, 0, 56.25, 0, 5),
        ];
        JointDefinition[] joints =
        [
            new("j1", "q1", -160 * deg, 160 * deg, "test"),
            new("j2", "q2", -225 * deg, 45 * deg, "test"),
            new("j3", "q3", -45 * deg, 225 * deg, "test"),
            new("j4", "q4", -110 * deg, 170 * deg, "test"),
            new("j5", "q5", -100 * deg, 100 * deg, "test"),
            new("j6", "q6", -266 * deg, 266 * deg, "test"),
        ];
        return new KinematicChain(rows, joints, "PUMA-like");
    }

    /// <summary>Deterministic joint vectors uniform within the limits (System.Random with a fixed seed).</summary>
    public static double[] RandomJoints(KinematicChain chain, Random random)
    {
        var q = new double[chain.JointCount];
        TestRobots.FillRandomJoints(chain, random, q);
        return q;
    }

    public static IkTarget TargetOf(KinematicChain chain, double[] q, OrientationAxes axes)
    {
        var state = chain.CreateState();
        state.Update(q);
        return new IkTarget(state.ToolPosition, state.ToolRotation, axes);
    }

    /// <summary>Checks by forward kinematics (not the solver's own bookkeeping) that q reaches the target.</summary>
    public static void AssertReaches(KinematicChain chain, in IkTarget target, double[] q)
    {
        Assert.True(chain.WithinLimits(q), $"joints outside limits: [{string.Join(", ", q)}]");
        var state = chain.CreateState();
        state.Update(q);
        var d = state.ToolPosition - target.Position;
        Assert.True(Math.Abs(d.X) <= PositionToleranceMm && Math.Abs(d.Y) <= PositionToleranceMm && Math.Abs(d.Z) <= PositionToleranceMm,
            $"position off by {d}");
        for (var column = 0; column < 3; column++)
        {
            if (((int)target.AxisMask & (1 << column)) != 0)
            {
                var angle = Angle(state.ToolRotation[column], target.Rotation[column]);
                Assert.True(angle <= OrientationToleranceRad, $"axis {column} off by {angle} rad");
            }
        }
    }

    /// <summary>Copies of <paramref name="q"/> with joint <paramref name="joint"/> moved by +h and -h, for central differences.</summary>
    public static (double[] Plus, double[] Minus) Nudged(double[] q, int joint, double h)
    {
        var plus = (double[])q.Clone();
        var minus = (double[])q.Clone();
        plus[joint] += h;
        minus[joint] -= h;
        return (plus, minus);
    }

    public static double Angle(Vector3d a, Vector3d b) => Math.Atan2(Vector3d.Cross(a, b).Length, Vector3d.Dot(a, b));
}
