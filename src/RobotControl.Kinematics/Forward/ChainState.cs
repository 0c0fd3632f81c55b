using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Forward;

/// <summary>
/// The frames of a <see cref="KinematicChain"/> for one joint vector, computed by the forward recursion
/// (docs/algorithms.md). Frame 0 is the base; frame i+1 follows DH row i. Not thread-safe; allocates
/// nothing after construction.
/// </summary>
public sealed class ChainState
{
    private readonly Vector3d[] _x;
    private readonly Vector3d[] _y;
    private readonly Vector3d[] _z;
    private readonly Vector3d[] _p;

    internal ChainState(KinematicChain chain)
    {
        Chain = chain;
        var n = chain.RowCount + 1;
        _x = new Vector3d[n];
        _y = new Vector3d[n];
        _z = new Vector3d[n];
        _p = new Vector3d[n];
        _x[0] = Vector3d.UnitX;
        _y[0] = Vector3d.UnitY;
        _z[0] = Vector3d.UnitZ;
        _p[0] = Vector3d.Zero;
    }

    /// <summary>The chain this state belongs to.</summary>
    public KinematicChain Chain { get; }

    /// <summary>Tool-tip position, mm.</summary>
    public Vector3d ToolPosition => _p[^1];

    /// <summary>Tool-tip orientation.</summary>
    public Rotation3d ToolRotation => new(_x[^1], _y[^1], _z[^1]);

    /// <summary>Tool-tip pose.</summary>
    public Pose ToolPose => new(ToolPosition, ToolRotation);

    /// <summary>Origin of frame <paramref name="frame"/> (0 = base).</summary>
    public Vector3d Origin(int frame) => _p[frame];

    /// <summary>Orientation of frame <paramref name="frame"/>.</summary>
    public Rotation3d Rotation(int frame) => new(_x[frame], _y[frame], _z[frame]);

    /// <summary>Axis of joint <paramref name="joint"/> in the base frame.</summary>
    public Vector3d JointAxis(int joint) => _z[Chain.RowOfJoint(joint)];

    /// <summary>A point on the axis of joint <paramref name="joint"/>.</summary>
    public Vector3d JointOrigin(int joint) => _p[Chain.RowOfJoint(joint)];

    /// <summary>Runs the forward recursion for joint vector <paramref name="q"/> (radians).</summary>
    public void Update(ReadOnlySpan<double> q)
    {
        var chain = Chain;
        if (q.Length < chain.JointCount)
        {
            throw new ArgumentException($"joint vector has {q.Length} values; the chain has {chain.JointCount} joints", nameof(q));
        }

        for (var i = 0; i < chain.RowCount; i++)
        {
            var joint = chain.RowJoint(i);
            var theta = chain.ThetaOffset(i) + (joint >= 0 ? q[joint] : 0.0);
            var (st, ct) = Math.SinCos(theta);
            var xi = _x[i];
            var zi = _z[i];
            var x1 = (xi * ct) + (_y[i] * st);
            var z1 = (zi * chain.CosAlpha(i)) + (Vector3d.Cross(x1, zi) * chain.SinAlpha(i));
            _x[i + 1] = x1;
            _z[i + 1] = z1;
            _y[i + 1] = Vector3d.Cross(z1, x1);
            _p[i + 1] = _p[i] + (zi * chain.D(i)) + (x1 * chain.A(i));
        }
    }

    /// <summary>
    /// Geometric Jacobian at the last <see cref="Update"/>: a 6 x n row-major matrix, rows vx, vy, vz (mm/rad) then
    /// wx, wy, wz (rad/rad). Column i = [z_i x (p_end - p_i); z_i].
    /// </summary>
    public void Jacobian(Span<double> jacobian)
    {
        var n = Chain.JointCount;
        if (jacobian.Length < 6 * n)
        {
            throw new ArgumentException($"needs room for 6 x {n} values", nameof(jacobian));
        }

        var end = ToolPosition;
        for (var j = 0; j < n; j++)
        {
            var frame = Chain.RowOfJoint(j);
            var z = _z[frame];
            var v = Vector3d.Cross(z, end - _p[frame]);
            jacobian[j] = v.X;
            jacobian[n + j] = v.Y;
            jacobian[(2 * n) + j] = v.Z;
            jacobian[(3 * n) + j] = z.X;
            jacobian[(4 * n) + j] = z.Y;
            jacobian[(5 * n) + j] = z.Z;
        }
    }
}
