namespace RobotControl.Definitions.Model;

/// <summary>The actuated tool: jaw range, lead screw and linkage (link dimensions may be unknown).</summary>
public sealed record ToolDefinition(
    double JawMinRad,
    double JawMaxRad,
    double LeadScrewMeanDiameterMm,
    double LeadScrewLeadMm,
    double LeadScrewThreadAngleRad,
    double LeadScrewFriction,
    double JawThetaAOffsetRad,
    double? L1Mm,
    double? L2Mm,
    double? L3Mm,
    double? DOffsetMm);

/// <summary>Where an arm sits: the right arm is the model; a mirrored arm reflects it in the robot's mirror plane.</summary>
public sealed record ArmPlacement(string Name, bool Mirrored, Vector3Data BaseOffsetMm);

/// <summary>A plain 3-vector of data from a file.</summary>
public readonly record struct Vector3Data(double X, double Y, double Z);

/// <summary>A two-joint cross-section of the joint space for capability analysis (radians once loaded).</summary>
public sealed record CrossSectionDefinition(
    int XJoint,
    double XMinRad,
    double XMaxRad,
    int YJoint,
    double YMinRad,
    double YMaxRad,
    double StepRad,
    IReadOnlyList<double> FixedRad,
    IReadOnlyList<int> JointsUsed);

/// <summary>Requirements from laparoscopic-surgery measurements.</summary>
public sealed record RequirementsDefinition(
    Vector3Data ForceN,
    Vector3Data VelocityMmPerS,
    double GrasperRollRadPerS);
