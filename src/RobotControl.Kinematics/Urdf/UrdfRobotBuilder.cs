using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Mirroring;

namespace RobotControl.Kinematics.Urdf;

/// <summary>
/// Turns a robot file into URDF links and joints. Root link <c>body</c>; per arm a fixed joint to <c>{arm}_base</c> at
/// the arm's base offset, then one joint per DH row: row k is entered through the fixed part of row k-1,
/// F = Rz(theta_offset) Tz(d) Tx(a) Rx(alpha), and turns about its z axis by the joint value (a fixed joint for a row
/// no joint drives), so composing the joints gives exactly the product of the DH transforms; a fixed joint to
/// <c>{arm}_tool</c> adds the last row's F.
/// <para>
/// A mirrored arm is the model conjugated by the reflection S = diag(M, 1), M = I - 2 n nᵀ: S T(q) S. Every fixed part
/// becomes S F S (rotation M R M, a proper rotation, translation M p) and every turn S Rz(q) S, a turn by q about
/// -M e_z, so the mirrored arm is again a chain of proper transforms with the same joint values and limits.
/// </para>
/// </summary>
internal static class UrdfRobotBuilder
{
    /// <summary>Name of the root link every arm is mounted on.</summary>
    public const string RootLink = "body";

    /// <summary>The robot's links and joints, arms in file order.</summary>
    public static (IReadOnlyList<UrdfLink> Links, IReadOnlyList<UrdfJoint> Joints) Build(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var radius = 0.08 * robot.Dh.Max(r => Math.Sqrt((r.AMm * r.AMm) + (r.DMm * r.DMm)));
        var links = new List<UrdfLink> { new(RootLink, null, 0, 0) };
        var joints = new List<UrdfJoint>();
        for (var arm = 0; arm < robot.Arms.Count; arm++)
        {
            AddArm(robot, arm, radius, links, joints);
        }

        return (links, joints);
    }

    private static void AddArm(RobotDefinition robot, int armIndex, double radius, List<UrdfLink> links, List<UrdfJoint> joints)
    {
        var arm = robot.Arms[armIndex];
        var n = robot.MirrorPlaneNormal;
        var normal = new Vector3d(n.X, n.Y, n.Z).Normalized();
        UrdfFrame Place(UrdfFrame f) => arm.Mirrored
            ? new UrdfFrame(ArmMirror.Reflect(f.Position, normal), ArmMirror.Reflect(f.Rotation, normal))
            : f;
        var axis = arm.Mirrored ? -ArmMirror.Reflect(Vector3d.UnitZ, normal) : Vector3d.UnitZ;

        var baseLink = $"{arm.Name}_base";
        links.Add(new UrdfLink(baseLink, null, 0, 0));
        var offset = new Vector3d(arm.BaseOffsetMm.X, arm.BaseOffsetMm.Y, arm.BaseOffsetMm.Z);
        joints.Add(new UrdfJoint($"{arm.Name}_mount", RootLink, baseLink, new UrdfFrame(offset, Rotation3d.Identity), Vector3d.UnitZ, null, armIndex, -1));

        var parent = baseLink;
        var entry = UrdfFrame.Identity;
        for (var k = 0; k < robot.Dh.Count; k++)
        {
            var row = robot.Dh[k];
            var fixedPart = Place(FixedPart(row));
            var link = $"{arm.Name}_link{k}";
            links.Add(Visual(link, fixedPart.Position, radius));
            var limits = row.IsFixed ? null : Limits(robot, armIndex, row.JointIndex);
            var name = row.IsFixed ? $"{arm.Name}_fixed{k}" : $"{arm.Name}_{robot.Joints[row.JointIndex].Name}";
            joints.Add(new UrdfJoint(name, parent, link, entry, axis, limits, armIndex, row.IsFixed ? -1 : row.JointIndex));
            parent = link;
            entry = fixedPart;
        }

        var tool = UrdfExport.ToolLinkName(arm.Name);
        links.Add(new UrdfLink(tool, null, 0, 0));
        joints.Add(new UrdfJoint($"{arm.Name}_tool_mount", parent, tool, entry, Vector3d.UnitZ, null, armIndex, -1));
    }

    /// <summary>Rz(theta_offset) Tz(d) Tx(a) Rx(alpha): the part of a DH row that does not move.</summary>
    private static UrdfFrame FixedPart(DhRow row)
    {
        var (s, c) = Math.SinCos(row.ThetaOffsetRad);
        return new UrdfFrame(
            new Vector3d(row.AMm * c, row.AMm * s, row.DMm),
            Rotation3d.AboutZ(row.ThetaOffsetRad) * Rotation3d.AboutX(row.AlphaRad));
    }

    /// <summary>A cylinder from the link's origin to its child joint, or a sphere where the two coincide.</summary>
    private static UrdfLink Visual(string name, Vector3d toChild, double radius)
    {
        var length = toChild.Length;
        return length < 1e-9
            ? new UrdfLink(name, UrdfFrame.Identity, 0, radius)
            : new UrdfLink(name, UrdfFrame.AlongZ(toChild * 0.5, toChild), length, radius);
    }

    /// <summary>
    /// The joint's range, the rated output torque of the axis the file lists against the joint (motor rated torque x
    /// reduction x efficiency) and the speed limit the arm's module keeps for that axis.
    /// </summary>
    private static UrdfLimits Limits(RobotDefinition robot, int armIndex, int jointIndex)
    {
        var joint = robot.Joints[jointIndex];
        var actuator = -1;
        for (var i = 0; i < robot.Actuators.Count; i++)
        {
            if (robot.Actuators[i].JointIndex == jointIndex)
            {
                actuator = i;
                break;
            }
        }

        if (actuator < 0)
        {
            return new UrdfLimits(joint.MinRad, joint.MaxRad, null, null);
        }

        var drivetrain = robot.Actuators[actuator].Drivetrain;
        var effort = robot.Motor(drivetrain.MotorModel).RatedTorqueMNm * drivetrain.TotalRatio * drivetrain.TotalEfficiency / 1000;
        double? velocity = null;
        foreach (var module in robot.Modules.Modules)
        {
            foreach (var motor in module.Motors)
            {
                if (module.Arm == armIndex && motor.ActuatorIndex == actuator)
                {
                    velocity = motor.SpeedLimitRadS;
                }
            }
        }

        return new UrdfLimits(joint.MinRad, joint.MaxRad, effort, velocity);
    }
}
