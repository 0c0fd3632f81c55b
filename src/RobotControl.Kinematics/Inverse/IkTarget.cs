using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Inverse;

/// <summary>
/// What the inverse kinematics aims for: a tool position (mm) and orientation, with <see cref="AxisMask"/> (sigma)
/// choosing which orientation axes (columns of <see cref="Rotation"/>) matter.
/// </summary>
/// <param name="Position">Target tool-tip position, mm, in the arm's base frame.</param>
/// <param name="Rotation">Target orientation (columns Rd1, Rd2, Rd3).</param>
/// <param name="AxisMask">sigma: which orientation axes count; <see cref="OrientationAxes.None"/> for position only.</param>
public readonly record struct IkTarget(Vector3d Position, Rotation3d Rotation, OrientationAxes AxisMask)
{
    /// <summary>A position-only target.</summary>
    public static IkTarget PositionOnly(Vector3d position) => new(position, Rotation3d.Identity, OrientationAxes.None);
}

/// <summary>sigma_j: which columns of the target rotation the error includes.</summary>
[Flags]
public enum OrientationAxes
{
    /// <summary>Position only.</summary>
    None = 0,

    /// <summary>The tool's x axis (Rd1).</summary>
    X = 1,

    /// <summary>The tool's y axis (Rd2).</summary>
    Y = 2,

    /// <summary>The tool's z axis (Rd3), e.g. the wrist-roll choice of a 4-DOF CRB arm.</summary>
    Z = 4,

    /// <summary>Full orientation.</summary>
    All = X | Y | Z,
}
