using RobotControl.Definitions.Model;

namespace RobotControl.Kinematics.Forward;

/// <summary>
/// A serial chain of standard DH rows with revolute joints, built from a robot file; immutable and shareable between
/// threads. Per-call state lives in a <see cref="ChainState"/>.
/// </summary>
public sealed class KinematicChain
{
    private readonly double[] _cosAlpha;
    private readonly double[] _sinAlpha;
    private readonly double[] _a;
    private readonly double[] _d;
    private readonly double[] _thetaOffset;
    private readonly int[] _rowJoint;
    private readonly int[] _jointRow;
    private readonly double[] _min;
    private readonly double[] _max;
    private readonly bool[] _fullTurn;

    /// <summary>Builds the chain of <paramref name="robot"/>'s arm.</summary>
    public KinematicChain(RobotDefinition robot)
        : this(robot?.Dh ?? throw new ArgumentNullException(nameof(robot)), robot.Joints, robot.Name)
    {
    }

    /// <summary>Builds a chain from DH rows and joint definitions.</summary>
    public KinematicChain(IReadOnlyList<DhRow> rows, IReadOnlyList<JointDefinition> joints, string name = "chain")
    {
        ArgumentNullException.ThrowIfNull(rows);
        ArgumentNullException.ThrowIfNull(joints);
        if (rows.Count == 0)
        {
            throw new ArgumentException("a chain needs at least one DH row", nameof(rows));
        }

        Name = name;
        RowCount = rows.Count;
        JointCount = joints.Count;
        _cosAlpha = rows.Select(r => Math.Cos(r.AlphaRad)).ToArray();
        _sinAlpha = rows.Select(r => Math.Sin(r.AlphaRad)).ToArray();
        _a = rows.Select(r => r.AMm).ToArray();
        _d = rows.Select(r => r.DMm).ToArray();
        _thetaOffset = rows.Select(r => r.ThetaOffsetRad).ToArray();
        _rowJoint = rows.Select(r => r.JointIndex).ToArray();
        _jointRow = new int[JointCount];
        Array.Fill(_jointRow, -1);
        for (var i = 0; i < rows.Count; i++)
        {
            if (rows[i].JointIndex >= JointCount)
            {
                throw new ArgumentException($"DH row {i} names joint {rows[i].JointIndex} of {JointCount}", nameof(rows));
            }

            if (rows[i].JointIndex >= 0)
            {
                _jointRow[rows[i].JointIndex] = i;
            }
        }

        if (_jointRow.Any(r => r < 0))
        {
            throw new ArgumentException("every joint must drive a DH row", nameof(joints));
        }

        _min = joints.Select(j => j.MinRad).ToArray();
        _max = joints.Select(j => j.MaxRad).ToArray();
        _fullTurn = joints.Select(j => j.MaxRad - j.MinRad >= (2 * Math.PI) - 1e-9).ToArray();
        Rows = rows;
        Joints = joints;
    }

    /// <summary>Name of the chain (the robot's).</summary>
    public string Name { get; }

    /// <summary>Number of DH rows.</summary>
    public int RowCount { get; }

    /// <summary>Number of joints (the length of a joint vector).</summary>
    public int JointCount { get; }

    /// <summary>DH rows.</summary>
    public IReadOnlyList<DhRow> Rows { get; }

    /// <summary>Joint definitions.</summary>
    public IReadOnlyList<JointDefinition> Joints { get; }

    /// <summary>Lower joint limits, radians.</summary>
    public ReadOnlySpan<double> MinRad => _min;

    /// <summary>Upper joint limits, radians.</summary>
    public ReadOnlySpan<double> MaxRad => _max;

    /// <summary>The DH row that joint <paramref name="joint"/> drives; its axis is the z axis of frame <c>row</c>.</summary>
    public int RowOfJoint(int joint) => _jointRow[joint];

    /// <summary>Creates a state (frame workspace) for this chain; reuse it for every call on one thread.</summary>
    public ChainState CreateState() => new(this);

    /// <summary>True when every joint of <paramref name="q"/> lies within its limits (with a tolerance in radians).</summary>
    public bool WithinLimits(ReadOnlySpan<double> q, double tolerance = 0)
    {
        for (var i = 0; i < JointCount; i++)
        {
            if (q[i] < _min[i] - tolerance || q[i] > _max[i] + tolerance)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>Clamps <paramref name="q"/> into the joint limits in place.</summary>
    public void Clamp(Span<double> q)
    {
        for (var i = 0; i < JointCount; i++)
        {
            q[i] = Math.Clamp(q[i], _min[i], _max[i]);
        }
    }

    /// <summary>Writes the middle of every joint range into <paramref name="q"/>.</summary>
    public void MidRange(Span<double> q)
    {
        for (var i = 0; i < JointCount; i++)
        {
            q[i] = 0.5 * (_min[i] + _max[i]);
        }
    }

    /// <summary>
    /// True when joint <paramref name="joint"/>'s range is a whole turn or more (a tool roll of ±180°): it has no real
    /// end, and a motion past one end re-enters at the other.
    /// </summary>
    internal bool IsFullTurn(int joint) => _fullTurn[joint];

    /// <summary><paramref name="value"/> brought into joint <paramref name="joint"/>'s range: by whole turns for a full-turn joint, then clamped.</summary>
    internal double IntoRange(int joint, double value)
    {
        var min = _min[joint];
        var max = _max[joint];
        if (_fullTurn[joint])
        {
            while (value > max)
            {
                value -= 2 * Math.PI;
            }

            while (value < min)
            {
                value += 2 * Math.PI;
            }
        }

        return Math.Clamp(value, min, max);
    }

    internal double CosAlpha(int row) => _cosAlpha[row];

    internal double SinAlpha(int row) => _sinAlpha[row];

    internal double A(int row) => _a[row];

    internal double D(int row) => _d[row];

    internal double ThetaOffset(int row) => _thetaOffset[row];

    internal int RowJoint(int row) => _rowJoint[row];
}
