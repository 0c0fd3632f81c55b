namespace RobotControl.Kinematics.Inverse;

/// <summary>Solver settings. Defaults are the platform's tuned values; the IK plug-in exposes them as settings.</summary>
public sealed record IkOptions
{
    /// <summary>Position tolerance, mm (0.01 mm = 1e-5 m, as TRAC-IK and KDL benchmark).</summary>
    public double PositionToleranceMm { get; init; } = 0.01;

    /// <summary>Orientation tolerance per selected axis, radians.</summary>
    public double OrientationToleranceRad { get; init; } = 1e-5;

    /// <summary>wp: weight of the position error (per mm²).</summary>
    public double PositionWeight { get; init; } = 1.0;

    /// <summary>wo: weight of the orientation error terms.</summary>
    public double OrientationWeight { get; init; } = 1e4;

    /// <summary>Workspace spring stiffness k_s, N/mm, for the force output when unreachable.</summary>
    public double WorkspaceStiffnessNPerMm { get; init; } = 0.05;

    /// <summary>Upper bound on work per solve (CCD cycles + Levenberg-Marquardt iterations), so the control loop's time is bounded.</summary>
    public int MaxIterations { get; init; } = 200;

    /// <summary>Random restarts allowed when stuck at a limit or local minimum (0 disables; deterministic seed).</summary>
    public int MaxRestarts { get; init; } = 8;
}
