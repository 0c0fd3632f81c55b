using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// One prepared IK target on one chain, with the frame workspace to evaluate it: the error E and its gradient exactly as
/// docs/algorithms.md defines them, and the least-squares form the damped Newton step works on. Allocates only in the
/// constructor; not thread-safe.
/// </summary>
/// <remarks>
/// Least-squares form: residual r = [sqrt(wp) (Ph - Pd); sqrt(wo) (Rh_j - Rd_j) for each selected axis j], so
/// |r|² = wp |Pd - Ph|² + 2 wo Σ σ_j (1 - Rd_j·Rh_j). That is the quantity the CCD step of docs/algorithms.md maximises
/// the complement of (k2 = wp Pid·Pih + wo Σ σ_j Rd_j·Rh_j), it has the same zero set as E, and it is linear rather than
/// quartic in the angle error, so Gauss-Newton converges quadratically on it where it would crawl on E.
/// </remarks>
internal sealed class IkProblem
{
    /// <summary>Targets farther than this (mm) are pulled in along their direction for the optimisation only.</summary>
    internal const double FarTargetMm = 1e6;

    private readonly ChainState _state;
    private readonly Vector3d[] _targetAxis = new Vector3d[3];
    private readonly int[] _selectedAxis = new int[3];
    private readonly double _chordToleranceSquared;

    // NormalEquations' workspace: per joint the Jacobian column as 4 blocks of 3 (position, then up to three axes),
    // and the residual in the same blocks.
    private readonly Vector3d[] _columns;
    private readonly Vector3d[] _residual = new Vector3d[4];

    internal IkProblem(KinematicChain chain, IkOptions options)
    {
        Chain = chain;
        _state = chain.CreateState();
        JointCount = chain.JointCount;
        _columns = new Vector3d[4 * chain.JointCount];
        PositionWeight = options.PositionWeight;
        OrientationWeight = options.OrientationWeight;
        SqrtPositionWeight = Math.Sqrt(PositionWeight);
        SqrtOrientationWeight = Math.Sqrt(OrientationWeight);
        PositionTolerance = options.PositionToleranceMm;
        OrientationTolerance = options.OrientationToleranceRad;
        var halfChord = Math.Sin(0.5 * Math.Min(options.OrientationToleranceRad, Math.PI));
        _chordToleranceSquared = 4 * halfChord * halfChord;
    }

    internal KinematicChain Chain { get; }

    internal ChainState State => _state;

    internal int JointCount { get; }

    internal double PositionWeight { get; }

    internal double OrientationWeight { get; }

    internal double SqrtPositionWeight { get; }

    internal double SqrtOrientationWeight { get; }

    internal double PositionTolerance { get; }

    internal double OrientationTolerance { get; }

    /// <summary>Pd used by the optimisation (the demanded point, pulled in if absurdly far).</summary>
    internal Vector3d TargetPosition { get; private set; }

    /// <summary>Number of selected orientation axes (0..3).</summary>
    internal int AxisCount { get; private set; }

    /// <summary>Residual length: 3 + 3 per selected axis.</summary>
    internal int ResidualCount => 3 + (3 * AxisCount);

    /// <summary>Target axis Rd_j of the k-th selected axis (unit length).</summary>
    internal Vector3d TargetAxis(int k) => _targetAxis[k];

    /// <summary>Column index (0 = x, 1 = y, 2 = z) of the k-th selected axis.</summary>
    internal int SelectedColumn(int k) => _selectedAxis[k];

    /// <summary>
    /// Prepares <paramref name="target"/>; false when it holds NaN or infinity in the position or a selected axis.
    /// Selected axes of zero length carry no direction and are dropped.
    /// </summary>
    internal bool SetTarget(in IkTarget target)
    {
        var p = target.Position;
        if (!p.IsFinite)
        {
            return false;
        }

        // Pulled in along its direction, taken from p scaled to its largest component: |p| itself overflows for a
        // target near the range of doubles, and FarTargetMm / ∞ would put the target at the origin.
        var norm = SafeLength(p);
        if (norm > FarTargetMm)
        {
            var scaled = p / Math.Max(Math.Abs(p.X), Math.Max(Math.Abs(p.Y), Math.Abs(p.Z)));
            p = scaled * (FarTargetMm / scaled.Length);
        }

        TargetPosition = p;
        AxisCount = 0;
        for (var column = 0; column < 3; column++)
        {
            if (((int)target.AxisMask & (1 << column)) == 0)
            {
                continue;
            }

            var axis = target.Rotation[column];
            if (!axis.IsFinite)
            {
                return false;
            }

            var length = SafeLength(axis);
            if (length > 0 && double.IsFinite(length))
            {
                var unit = axis / length;
                _targetAxis[AxisCount] = unit / unit.Length;
                _selectedAxis[AxisCount] = column;
                AxisCount++;
            }
        }

        return true;
    }

    /// <summary>Runs forward kinematics for <paramref name="q"/> and returns the least-squares cost |r|².</summary>
    internal double Evaluate(ReadOnlySpan<double> q)
    {
        _state.Update(q);
        return CurrentCost();
    }

    /// <summary>|r|² at the last <see cref="Evaluate"/>.</summary>
    internal double CurrentCost()
    {
        var cost = PositionWeight * (_state.ToolPosition - TargetPosition).LengthSquared;
        var rotation = _state.ToolRotation;
        for (var k = 0; k < AxisCount; k++)
        {
            cost += OrientationWeight * (rotation[_selectedAxis[k]] - _targetAxis[k]).LengthSquared;
        }

        return cost;
    }

    /// <summary>
    /// At the last <see cref="Evaluate"/>: the Gauss-Newton normal matrix JᵀJ (n x n, row-major) and Jᵀr, with J the
    /// exact Jacobian of the residual (dPh/dθ_i = z_i x (Ph - p_i), dRh_j/dθ_i = z_i x Rh_j).
    /// </summary>
    internal void NormalEquations(Span<double> jacobian, Span<double> normal, Span<double> jtr)
    {
        var n = JointCount;
        var axisCount = AxisCount;
        var end = _state.ToolPosition;
        var rotation = _state.ToolRotation;
        var columns = _columns.AsSpan();
        var residual = _residual.AsSpan();
        residual[0] = (end - TargetPosition) * SqrtPositionWeight;
        for (var k = 0; k < axisCount; k++)
        {
            residual[1 + k] = (rotation[_selectedAxis[k]] - _targetAxis[k]) * SqrtOrientationWeight;
        }

        // Column i of J in 3-vector blocks: the position block, then one block per selected axis.
        for (var i = 0; i < n; i++)
        {
            var z = _state.JointAxis(i);
            var v = Vector3d.Cross(z, end - _state.JointOrigin(i)) * SqrtPositionWeight;
            columns[i * 4] = v;
            jacobian[i] = v.X;
            jacobian[n + i] = v.Y;
            jacobian[(2 * n) + i] = v.Z;
            for (var k = 0; k < axisCount; k++)
            {
                var w = Vector3d.Cross(z, rotation[_selectedAxis[k]]) * SqrtOrientationWeight;
                columns[(i * 4) + 1 + k] = w;
                var row = 3 + (3 * k);
                jacobian[(row * n) + i] = w.X;
                jacobian[((row + 1) * n) + i] = w.Y;
                jacobian[((row + 2) * n) + i] = w.Z;
            }
        }

        for (var i = 0; i < n; i++)
        {
            var ci = columns.Slice(i * 4, 1 + axisCount);
            var s = 0.0;
            for (var b = 0; b < ci.Length; b++)
            {
                s += Vector3d.Dot(ci[b], residual[b]);
            }

            jtr[i] = s;
            for (var j = 0; j <= i; j++)
            {
                var cj = columns.Slice(j * 4, ci.Length);
                var a = 0.0;
                for (var b = 0; b < ci.Length; b++)
                {
                    a += Vector3d.Dot(ci[b], cj[b]);
                }

                normal[(i * n) + j] = a;
                normal[(j * n) + i] = a;
            }
        }
    }

    /// <summary>E = wp |Pd - Ph|² + wo Σ σ_j (Rd_j·Rh_j - 1)² (docs/algorithms.md) at the last <see cref="Evaluate"/>.</summary>
    internal double SpecError()
    {
        var e = PositionWeight * (TargetPosition - _state.ToolPosition).LengthSquared;
        var rotation = _state.ToolRotation;
        for (var k = 0; k < AxisCount; k++)
        {
            var c = Vector3d.Dot(_targetAxis[k], rotation[_selectedAxis[k]]) - 1;
            e += OrientationWeight * c * c;
        }

        return e;
    }

    /// <summary>
    /// dE/dθ_i = -2 wp z_i·(Pih x (Pd - Ph)) + wo Σ σ_j 2 (Rd_j·Rh_j - 1) z_i·(Rh_j x Rd_j) (docs/algorithms.md) at the last
    /// <see cref="Evaluate"/>.
    /// </summary>
    internal void SpecGradient(Span<double> gradient)
    {
        var end = _state.ToolPosition;
        var rotation = _state.ToolRotation;
        var toTarget = TargetPosition - end;
        for (var i = 0; i < JointCount; i++)
        {
            var z = _state.JointAxis(i);
            var pih = end - _state.JointOrigin(i);
            var g = -2 * PositionWeight * Vector3d.Dot(z, Vector3d.Cross(pih, toTarget));
            for (var k = 0; k < AxisCount; k++)
            {
                var rh = rotation[_selectedAxis[k]];
                var rd = _targetAxis[k];
                g += OrientationWeight * 2 * (Vector3d.Dot(rd, rh) - 1) * Vector3d.Dot(z, Vector3d.Cross(rh, rd));
            }

            gradient[i] = g;
        }
    }

    /// <summary>
    /// True when the last <see cref="Evaluate"/> is within tolerance: every position component within the position
    /// tolerance of the target and every selected axis within the orientation tolerance.
    /// </summary>
    internal bool WithinTolerance()
    {
        var d = _state.ToolPosition - TargetPosition;
        if (Math.Abs(d.X) > PositionTolerance || Math.Abs(d.Y) > PositionTolerance || Math.Abs(d.Z) > PositionTolerance)
        {
            return false;
        }

        // Angle within tolerance <=> chord |Rh_j - Rd_j| within 2 sin(tol/2): exact, and no atan2 in the loop.
        var rotation = _state.ToolRotation;
        for (var k = 0; k < AxisCount; k++)
        {
            if ((rotation[_selectedAxis[k]] - _targetAxis[k]).LengthSquared > _chordToleranceSquared)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Largest angle between a selected target axis and the reached one at the last <see cref="Evaluate"/>.</summary>
    internal double LargestAxisAngle()
    {
        var rotation = _state.ToolRotation;
        var largest = 0.0;
        for (var k = 0; k < AxisCount; k++)
        {
            largest = Math.Max(largest, AngleBetween(rotation[_selectedAxis[k]], _targetAxis[k]));
        }

        return largest;
    }

    /// <summary>Angle between two vectors, accurate near 0 and π.</summary>
    internal static double AngleBetween(Vector3d a, Vector3d b) =>
        Math.Atan2(Vector3d.Cross(a, b).Length, Vector3d.Dot(a, b));

    /// <summary>Euclidean length without overflow for huge components; never NaN for finite input.</summary>
    internal static double SafeLength(Vector3d v)
    {
        var scale = Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));
        if (scale == 0 || !double.IsFinite(scale))
        {
            return scale;
        }

        return scale * (v / scale).Length;
    }
}
