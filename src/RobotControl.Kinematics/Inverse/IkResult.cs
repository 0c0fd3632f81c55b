using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// Outcome of one solve. The joint vector is written to the caller's span; this value carries the rest. Never holds
/// NaN: an unreachable or degenerate target gives the best reachable pose and a finite workspace force.
/// </summary>
/// <param name="Status">Whether the target was reached within tolerance.</param>
/// <param name="ReachedPosition">Tool position of the returned joint vector (Ph), mm.</param>
/// <param name="PositionErrorMm">|Pd - Ph|, mm.</param>
/// <param name="OrientationErrorRad">Largest angle between a selected target axis and the reached one, radians.</param>
/// <param name="WorkspaceForce">k_s (Ph - Pd) in the arm's base frame, newtons (zero when reached), before any per-axis clamp.</param>
/// <param name="Iterations">CCD cycles plus Levenberg-Marquardt iterations used (never more than <see cref="IkOptions.MaxIterations"/>).</param>
/// <param name="AtCeiling">
/// Not reached because the iteration ceiling (<see cref="IkOptions.MaxIterations"/>) ran out: the pose is the best one
/// found, and the target may still be reachable. False when reached, and when every start stalled before the ceiling.
/// </param>
public readonly record struct IkResult(
    IkStatus Status,
    Vector3d ReachedPosition,
    double PositionErrorMm,
    double OrientationErrorRad,
    Vector3d WorkspaceForce,
    int Iterations,
    bool AtCeiling = false)
{
    /// <summary>True when the target was reached within tolerance.</summary>
    public bool Reached => Status == IkStatus.Reached;
}

/// <summary>Solve status.</summary>
public enum IkStatus
{
    /// <summary>Within the position and orientation tolerances.</summary>
    Reached,

    /// <summary>Not reachable (outside the workspace or the joint limits): the best reachable pose is returned.</summary>
    Unreachable,

    /// <summary>The target held NaN or infinity: the seed is returned unchanged with zero force.</summary>
    InvalidTarget,
}
