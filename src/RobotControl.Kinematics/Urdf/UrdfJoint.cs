using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Urdf;

/// <summary>One URDF joint: parent link -> child link through <see cref="Origin"/>, then a turn about <see cref="Axis"/> for a revolute joint.</summary>
/// <param name="Name">Joint name, e.g. <c>right_elbow</c>.</param>
/// <param name="Parent">Parent link name.</param>
/// <param name="Child">Child link name.</param>
/// <param name="Origin">Parent -> joint frame transform.</param>
/// <param name="Axis">Rotation axis in the joint frame (unit), for a revolute joint.</param>
/// <param name="Limits">Limits of a revolute joint; null for a fixed joint.</param>
/// <param name="Arm">Index of the arm the joint belongs to (the robot file's order).</param>
/// <param name="JointIndex">Index of the robot file's joint that turns it, or -1 for a fixed joint.</param>
internal sealed record UrdfJoint(string Name, string Parent, string Child, UrdfFrame Origin, Vector3d Axis, UrdfLimits? Limits, int Arm, int JointIndex)
{
    /// <summary>True for a revolute joint.</summary>
    public bool IsRevolute => Limits is not null;
}

/// <summary>Limits of a revolute joint.</summary>
/// <param name="LowerRad">Lower limit, radians.</param>
/// <param name="UpperRad">Upper limit, radians.</param>
/// <param name="EffortNm">Maximum joint torque, N·m (null when the robot file gives no drivetrain for the joint).</param>
/// <param name="VelocityRadS">Maximum joint speed, rad/s (null when the robot file gives no speed limit for the joint).</param>
internal sealed record UrdfLimits(double LowerRad, double UpperRad, double? EffortNm, double? VelocityRadS);

/// <summary>One URDF link with an optional cylinder (visual) from its origin towards its child joint.</summary>
/// <param name="Name">Link name.</param>
/// <param name="Visual">Where the cylinder sits (its z axis is the cylinder's axis), or null for no visual.</param>
/// <param name="LengthMm">Cylinder length, mm (0 for a sphere).</param>
/// <param name="RadiusMm">Cylinder or sphere radius, mm.</param>
internal sealed record UrdfLink(string Name, UrdfFrame? Visual, double LengthMm, double RadiusMm);
