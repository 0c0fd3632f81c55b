namespace RobotControl.Definitions.Model;

/// <summary>
/// A driven axis: one motor, its gearhead and the spur/bevel stages after it. The motor turns
/// <see cref="Coupling"/> · q (a linear combination of joint angles) at the output, e.g. the upper sun gear of a
/// differential shoulder turns phi1 + phi2.
/// </summary>
/// <param name="Name">Axis name, e.g. <c>shoulder_1</c>.</param>
/// <param name="Label">Human-readable label.</param>
/// <param name="JointIndex">The joint this axis is listed against in the design's drivetrain table (-1 for the tool jaw).</param>
/// <param name="Coupling">Coefficient per joint (length = joint count); all zeros for an axis that drives no kinematic joint.</param>
/// <param name="Drivetrain">The drivetrain.</param>
public sealed record ActuatorDefinition(
    string Name,
    string Label,
    int JointIndex,
    IReadOnlyList<double> Coupling,
    DrivetrainDefinition Drivetrain)
{
    /// <summary>True when the axis drives a kinematic joint (false for the tool's open/close drive).</summary>
    public bool IsKinematic => JointIndex >= 0;
}

/// <summary>Drivetrain of one axis: motor, planetary gearhead, then <see cref="MeshesAfterGearhead"/> spur/bevel meshes.</summary>
/// <param name="MeshesAfterGearhead">n: gear meshes after the gearhead (each 95 % efficient).</param>
/// <param name="StageOutputTeeth">Teeth on the driven gear of the stage after the gearhead.</param>
/// <param name="StageInputTeeth">Teeth on the driving gear of the stage after the gearhead.</param>
/// <param name="GearheadSeries">Gearhead series, e.g. <c>12/4</c>.</param>
/// <param name="GearheadRatio">Gearhead reduction, e.g. 256.</param>
/// <param name="GearheadEfficiency">Gearhead efficiency, 0..1.</param>
/// <param name="MotorModel">Motor model, e.g. <c>1226 S 012 B</c>.</param>
/// <param name="Note">Free-text note (assumptions, discrepancies).</param>
public sealed record DrivetrainDefinition(
    int MeshesAfterGearhead,
    int StageOutputTeeth,
    int StageInputTeeth,
    string GearheadSeries,
    double GearheadRatio,
    double GearheadEfficiency,
    string MotorModel,
    string? Note)
{
    /// <summary>Efficiency of one spur/bevel mesh.</summary>
    public const double MeshEfficiency = 0.95;

    /// <summary>tau: the spur/bevel reduction after the gearhead.</summary>
    public double StageRatio => (double)StageOutputTeeth / StageInputTeeth;

    /// <summary>Total reduction motor -> joint (tau · tau_m).</summary>
    public double TotalRatio => StageRatio * GearheadRatio;

    /// <summary>Total efficiency eta^n · eta_m.</summary>
    public double TotalEfficiency => Math.Pow(MeshEfficiency, MeshesAfterGearhead) * GearheadEfficiency;
}
