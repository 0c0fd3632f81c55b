using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Sweep;

/// <summary>
/// A two-joint grid over the joint space: joint <see cref="XJoint"/> from <see cref="XMinRad"/> to
/// <see cref="XMaxRad"/> and joint <see cref="YJoint"/> likewise, both ends included, every other joint at its
/// <see cref="FixedRad"/> value. Velocity, force and manipulability use the joints in <see cref="JointsUsed"/>.
/// </summary>
public sealed record SweepSpecification
{
    /// <summary>Creates a specification; ranges, step and joint indices are checked.</summary>
    public SweepSpecification(
        int xJoint,
        double xMinRad,
        double xMaxRad,
        int yJoint,
        double yMinRad,
        double yMaxRad,
        double stepRad,
        IReadOnlyList<double> fixedRad,
        IReadOnlyList<int> jointsUsed)
    {
        ArgumentNullException.ThrowIfNull(fixedRad);
        ArgumentNullException.ThrowIfNull(jointsUsed);
        if (!(stepRad > 0) || !double.IsFinite(stepRad))
        {
            throw new ArgumentException("the sweep step must be positive", nameof(stepRad));
        }

        if (xJoint == yJoint)
        {
            throw new ArgumentException("the two swept joints must differ", nameof(yJoint));
        }

        if (!(xMaxRad >= xMinRad) || !(yMaxRad >= yMinRad))
        {
            throw new ArgumentException("each sweep range needs min <= max");
        }

        if (xJoint < 0 || yJoint < 0 || xJoint >= fixedRad.Count || yJoint >= fixedRad.Count)
        {
            throw new ArgumentException("swept joint index out of range");
        }

        if (jointsUsed.Count < 3 || jointsUsed.Any(j => j < 0 || j >= fixedRad.Count) || jointsUsed.Distinct().Count() != jointsUsed.Count)
        {
            throw new ArgumentException("the analysis needs at least three distinct used joints (position Jacobian 3 x n, n >= 3)", nameof(jointsUsed));
        }

        XJoint = xJoint;
        XMinRad = xMinRad;
        XMaxRad = xMaxRad;
        YJoint = yJoint;
        YMinRad = yMinRad;
        YMaxRad = yMaxRad;
        StepRad = stepRad;
        FixedRad = fixedRad.ToArray();
        JointsUsed = jointsUsed.ToArray();
    }

    /// <summary>Joint index on the grid's first axis.</summary>
    public int XJoint { get; }

    /// <summary>First axis start, radians.</summary>
    public double XMinRad { get; }

    /// <summary>First axis end (included when on the step grid), radians.</summary>
    public double XMaxRad { get; }

    /// <summary>Joint index on the grid's second axis.</summary>
    public int YJoint { get; }

    /// <summary>Second axis start, radians.</summary>
    public double YMinRad { get; }

    /// <summary>Second axis end, radians.</summary>
    public double YMaxRad { get; }

    /// <summary>Grid step on both axes, radians.</summary>
    public double StepRad { get; }

    /// <summary>Value of every joint (joint-vector order); the swept joints' entries are ignored.</summary>
    public IReadOnlyList<double> FixedRad { get; }

    /// <summary>Joints whose Jacobian columns and drives count (the reference design: the position joints).</summary>
    public IReadOnlyList<int> JointsUsed { get; }

    /// <summary>Grid points on the first axis.</summary>
    public int XCount => StepCount(XMinRad, XMaxRad, StepRad);

    /// <summary>Grid points on the second axis.</summary>
    public int YCount => StepCount(YMinRad, YMaxRad, StepRad);

    /// <summary>Value of the first joint at grid index <paramref name="i"/>.</summary>
    public double XAt(int i) => XMinRad + (i * StepRad);

    /// <summary>Value of the second joint at grid index <paramref name="i"/>.</summary>
    public double YAt(int i) => YMinRad + (i * StepRad);

    /// <summary>The reference design's cross-section stored in a robot file.</summary>
    public static SweepSpecification FromCrossSection(CrossSectionDefinition crossSection)
    {
        ArgumentNullException.ThrowIfNull(crossSection);
        return new SweepSpecification(
            crossSection.XJoint,
            crossSection.XMinRad,
            crossSection.XMaxRad,
            crossSection.YJoint,
            crossSection.YMinRad,
            crossSection.YMaxRad,
            crossSection.StepRad,
            crossSection.FixedRad,
            crossSection.JointsUsed);
    }

    // The end is included when it lies on the grid; a tolerance absorbs degree-to-radian rounding.
    private static int StepCount(double min, double max, double step) => (int)Math.Floor(((max - min) / step) + 1e-9) + 1;
}
