namespace RobotControl.Analysis.Sweep;

/// <summary>
/// Per-point results of a capability sweep. Point index = x index · <see cref="YCount"/> + y index (the x joint is
/// the outer loop, as in the reference design).
/// </summary>
public sealed class SweepResult
{
    internal SweepResult(SweepSpecification specification, int jointCount, bool couplingAware)
    {
        Specification = specification;
        XCount = specification.XCount;
        YCount = specification.YCount;
        var n = XCount * YCount;
        JointCount = jointCount;
        Position = [new double[n], new double[n], new double[n]];
        Manipulability = new double[n];
        ManipulabilityNormalised = new double[n];
        Reference = new CapabilityMaps(n);
        CouplingAware = couplingAware ? new CapabilityMaps(n) : null;
    }

    /// <summary>The grid.</summary>
    public SweepSpecification Specification { get; }

    /// <summary>Points along the x joint.</summary>
    public int XCount { get; }

    /// <summary>Points along the y joint.</summary>
    public int YCount { get; }

    /// <summary>Number of points.</summary>
    public int Count => XCount * YCount;

    /// <summary>Joints in the robot's joint vector.</summary>
    public int JointCount { get; }

    /// <summary>Tool position X, Y, Z (index 0..2) per point, mm (right arm, base frame).</summary>
    public double[][] Position { get; }

    /// <summary>Manipulability sqrt(det(J Jᵀ)) of the used joints' position Jacobian per point, mm³.</summary>
    public double[] Manipulability { get; }

    /// <summary>Manipulability divided by its maximum over the grid.</summary>
    public double[] ManipulabilityNormalised { get; }

    /// <summary>The reference design's method (independent per-joint limits).</summary>
    public CapabilityMaps Reference { get; }

    /// <summary>The coupling-aware method, when requested.</summary>
    public CapabilityMaps? CouplingAware { get; }

    /// <summary>The full joint vector at point <paramref name="index"/>, radians.</summary>
    public void JointsAt(int index, Span<double> q)
    {
        var spec = Specification;
        for (var j = 0; j < JointCount; j++)
        {
            q[j] = spec.FixedRad[j];
        }

        q[spec.XJoint] = spec.XAt(index / YCount);
        q[spec.YJoint] = spec.YAt(index % YCount);
    }
}
