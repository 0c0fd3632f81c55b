using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Urdf;

/// <summary>
/// The transforms between the links of the exported URDF (<see cref="UrdfExport"/>), parent to child, one per URDF
/// joint, at given joint values: what a robot state publisher puts on <c>/tf</c>, so that a 3D tool given the URDF
/// draws each arm in the recorded pose. Built from the same links and joints the URDF is written from.
/// </summary>
public sealed class UrdfLinkFrames
{
    private readonly UrdfJoint[] _joints;

    /// <summary>The frames of <paramref name="robot"/>'s URDF.</summary>
    public UrdfLinkFrames(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        _joints = [.. UrdfRobotBuilder.Build(robot).Joints];
    }

    /// <summary>Transforms (URDF joints), arms in file order.</summary>
    public int Count => _joints.Length;

    /// <summary>The parent link of transform <paramref name="i"/>.</summary>
    public string Parent(int i) => _joints[i].Parent;

    /// <summary>The child link of transform <paramref name="i"/>.</summary>
    public string Child(int i) => _joints[i].Child;

    /// <summary>The arm (robot file order) transform <paramref name="i"/> belongs to.</summary>
    public int Arm(int i) => _joints[i].Arm;

    /// <summary>Transform <paramref name="i"/> (child in parent, mm) with its arm's joints at <paramref name="armJointsRad"/> (robot file order).</summary>
    public (Vector3d PositionMm, Rotation3d Rotation) Transform(int i, ReadOnlySpan<double> armJointsRad)
    {
        var joint = _joints[i];
        var rotation = joint.JointIndex < 0 ? joint.Origin.Rotation : joint.Origin.Rotation * Rotation3d.AboutAxis(joint.Axis, armJointsRad[joint.JointIndex]);
        return (joint.Origin.Position, rotation);
    }
}
