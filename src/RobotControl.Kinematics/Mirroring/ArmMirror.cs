using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Mirroring;

/// <summary>
/// Mirroring for the left arm (docs/robots.md; docs/algorithms.md, the left arm). Both robots are modelled as the RIGHT arm; the left arm
/// is its mirror image in the plane through the body origin with the robot file's <c>mirror_plane_normal</c> n, so one
/// kinematic model serves both arms: a left-arm target is reflected into the right-arm model, solved there, and the
/// joint vector is sent to the left arm's (mirror-built) joints unchanged.
/// <para>
/// The reflection M = I - 2 n nᵀ reverses handedness (det M = -1): reflecting the three axes of a frame gives a
/// left-handed frame, which is not a rotation. A reflected orientation R is therefore returned as M R M, a proper
/// rotation (det +1): the reflected axes M x, M y, M z with the component along n of each re-expressed through M again.
/// For the files' normal n = y this is exactly "reflect every column, then negate the y column":
/// M R M = [M x, -M y, M z]; the tool's z axis (along the forearm) is reflected like a point, as it must be.
/// Mirroring twice gives back the input (M² = I).
/// </para>
/// Each arm sits at its <c>base_offset_mm</c> from the body origin; the left arm's offset is the reflection of the
/// right arm's. Immutable, allocation-free, thread-safe.
/// </summary>
public sealed class ArmMirror
{
    /// <summary>Builds the mirror of <paramref name="robot"/>'s arm named <paramref name="armName"/> (default the left arm).</summary>
    /// <exception cref="ArgumentException">The robot has no arm of that name.</exception>
    public ArmMirror(RobotDefinition robot, string armName = "left")
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(armName);
        var arm = robot.Arms.FirstOrDefault(a => a.Name == armName)
            ?? throw new ArgumentException($"{robot.Name} has no arm \"{armName}\" (arms: {string.Join(", ", robot.Arms.Select(a => a.Name))})", nameof(armName));
        var n = robot.MirrorPlaneNormal;
        Normal = UnitNormal(new Vector3d(n.X, n.Y, n.Z));
        BaseOffsetMm = new Vector3d(arm.BaseOffsetMm.X, arm.BaseOffsetMm.Y, arm.BaseOffsetMm.Z);
        IsMirrored = arm.Mirrored;
        ArmName = arm.Name;
    }

    /// <summary>A mirror for a plane through the origin with normal <paramref name="planeNormal"/>.</summary>
    /// <param name="planeNormal">Normal of the mirror plane (any non-zero length).</param>
    /// <param name="baseOffsetMm">Where the arm's base sits in the body frame, mm.</param>
    /// <param name="isMirrored">True for the mirrored (left) arm.</param>
    public ArmMirror(Vector3d planeNormal, Vector3d baseOffsetMm, bool isMirrored = true)
    {
        Normal = UnitNormal(planeNormal);
        BaseOffsetMm = baseOffsetMm;
        IsMirrored = isMirrored;
        ArmName = isMirrored ? "left" : "right";
    }

    /// <summary>Name of the arm this mirror places.</summary>
    public string ArmName { get; }

    /// <summary>Unit normal of the mirror plane (through the body origin).</summary>
    public Vector3d Normal { get; }

    /// <summary>The arm's base position in the body frame, mm.</summary>
    public Vector3d BaseOffsetMm { get; }

    /// <summary>True when the arm is the mirror image of the model (the left arm).</summary>
    public bool IsMirrored { get; }

    /// <summary>Reflects a point or direction in the plane through the origin with unit normal <paramref name="unitNormal"/>.</summary>
    public static Vector3d Reflect(Vector3d v, Vector3d unitNormal) => v - (unitNormal * (2 * Vector3d.Dot(unitNormal, v)));

    /// <summary>The proper rotation M R M mirroring orientation <paramref name="rotation"/> (see the class remarks).</summary>
    public static Rotation3d Reflect(Rotation3d rotation, Vector3d unitNormal)
    {
        // Columns of M R M are M R (M e_k): reflect the rows' basis first, then each resulting column.
        var mx = Reflect(Vector3d.UnitX, unitNormal);
        var my = Reflect(Vector3d.UnitY, unitNormal);
        var mz = Reflect(Vector3d.UnitZ, unitNormal);
        return new Rotation3d(
            Reflect(rotation.Apply(mx), unitNormal),
            Reflect(rotation.Apply(my), unitNormal),
            Reflect(rotation.Apply(mz), unitNormal));
    }

    /// <summary>Reflects a pose (position and orientation) in the plane through the origin with unit normal <paramref name="unitNormal"/>.</summary>
    /// <remarks>The homing plug-in uses this to mirror the input device's pose for the left arm.</remarks>
    public static Pose Reflect(Pose pose, Vector3d unitNormal) =>
        new(Reflect(pose.Position, unitNormal), Reflect(pose.Rotation, unitNormal));

    /// <summary>Reflects a point or direction in this mirror's plane.</summary>
    public Vector3d MirrorPoint(Vector3d point) => Reflect(point, Normal);

    /// <summary>Mirrors an orientation in this mirror's plane (a proper rotation, see the class remarks).</summary>
    public Rotation3d MirrorRotation(Rotation3d rotation) => Reflect(rotation, Normal);

    /// <summary>
    /// A point in the body frame as the target of the right-arm model: relative to the arm's base and, for the
    /// mirrored arm, reflected.
    /// </summary>
    public Vector3d BodyToModel(Vector3d bodyPoint)
    {
        var relative = bodyPoint - BaseOffsetMm;
        return IsMirrored ? MirrorPoint(relative) : relative;
    }

    /// <summary>A point of the right-arm model (e.g. its forward kinematics) where this arm puts it in the body frame.</summary>
    public Vector3d ModelToBody(Vector3d modelPoint) => (IsMirrored ? MirrorPoint(modelPoint) : modelPoint) + BaseOffsetMm;

    /// <summary>A pose in the body frame as a target pose of the right-arm model.</summary>
    public Pose BodyToModel(Pose bodyPose) =>
        new(BodyToModel(bodyPose.Position), IsMirrored ? MirrorRotation(bodyPose.Rotation) : bodyPose.Rotation);

    /// <summary>A pose of the right-arm model where this arm puts it in the body frame.</summary>
    public Pose ModelToBody(Pose modelPose) =>
        new(ModelToBody(modelPose.Position), IsMirrored ? MirrorRotation(modelPose.Rotation) : modelPose.Rotation);

    private static Vector3d UnitNormal(Vector3d normal)
    {
        var length = normal.Length;
        if (!(length > 1e-9) || !double.IsFinite(length))
        {
            throw new ArgumentException("the mirror plane normal must be a finite, non-zero vector", nameof(normal));
        }

        return normal / length;
    }
}
