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

    /// <summary>
    /// Hard ceiling on work per solve (CCD cycles + Levenberg-Marquardt trial steps), so the control loop's time is
    /// bounded: a solve never reports more, and one that meets it returns the best pose found with
    /// <see cref="IkResult.AtCeiling"/>. The time per iteration is measured in docs/perf/ik.md.
    /// </summary>
    public int MaxIterations { get; init; } = 200;

    /// <summary>
    /// Restarts allowed when a run stalls at a limit or a local minimum: hops along a singular pose's free direction,
    /// then the nearest unused fixed seeds (deterministic). 0 disables them, which keeps tracking continuous.
    /// </summary>
    public int MaxRestarts { get; init; } = 32;
}
