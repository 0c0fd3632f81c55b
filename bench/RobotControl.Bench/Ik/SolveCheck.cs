using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// The one success criterion applied to every solver's answer, by our forward kinematics: joints within limits (after
/// wrapping by whole turns, which a revolute joint may do), every position component within 0.01 mm and every selected
/// orientation axis within 1e-5 rad.
/// </summary>
internal sealed class SolveCheck(KinematicChain chain, double positionMm, double orientationRad)
{
    private readonly ChainState _state = chain.CreateState();

    public double PositionMm { get; } = positionMm;

    public double OrientationRad { get; } = orientationRad;

    /// <summary>Wraps joints into their ranges by whole turns where possible; false if some joint stays outside.</summary>
    public bool WrapIntoLimits(Span<double> q)
    {
        var ok = true;
        for (var i = 0; i < chain.JointCount; i++)
        {
            if (!double.IsFinite(q[i]))
            {
                return false;
            }

            var min = chain.MinRad[i];
            var max = chain.MaxRad[i];
            var v = q[i];
            while (v > max + 1e-12 && v - (2 * Math.PI) >= min - 1e-12)
            {
                v -= 2 * Math.PI;
            }

            while (v < min - 1e-12 && v + (2 * Math.PI) <= max + 1e-12)
            {
                v += 2 * Math.PI;
            }

            q[i] = v;
            ok &= v >= min - 1e-9 && v <= max + 1e-9;
        }

        return ok;
    }

    public bool Solved(in IkTarget target, Span<double> q) => WrapIntoLimits(q) && WithinTolerance(target, q);

    /// <summary>The pose test alone, ignoring joint limits (for solvers that do not know them).</summary>
    public bool WithinTolerance(in IkTarget target, ReadOnlySpan<double> q)
    {
        foreach (var v in q)
        {
            if (!double.IsFinite(v))
            {
                return false;
            }
        }

        _state.Update(q);
        var d = _state.ToolPosition - target.Position;
        if (Math.Abs(d.X) > PositionMm || Math.Abs(d.Y) > PositionMm || Math.Abs(d.Z) > PositionMm)
        {
            return false;
        }

        var rotation = _state.ToolRotation;
        for (var column = 0; column < 3; column++)
        {
            if (((int)target.AxisMask & (1 << column)) != 0)
            {
                var a = rotation[column];
                var b = target.Rotation[column];
                if (Math.Atan2(Vector3d.Cross(a, b).Length, Vector3d.Dot(a, b)) > OrientationRad)
                {
                    return false;
                }
            }
        }

        return true;
    }
}
