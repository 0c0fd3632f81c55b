using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Urdf;

/// <summary>
/// A rigid transform as URDF writes it: translation (mm here, metres in the file) and a rotation given as roll, pitch,
/// yaw with R = Rz(yaw) Ry(pitch) Rx(roll).
/// </summary>
/// <param name="Position">Translation, mm.</param>
/// <param name="Rotation">Rotation.</param>
internal readonly record struct UrdfFrame(Vector3d Position, Rotation3d Rotation)
{
    /// <summary>The identity transform.</summary>
    public static UrdfFrame Identity => new(Vector3d.Zero, Rotation3d.Identity);

    /// <summary>
    /// Roll, pitch, yaw of <see cref="Rotation"/>; at pitch ±90° (where only yaw - roll or yaw + roll is defined) roll
    /// is taken as 0 and the whole turn goes into yaw.
    /// </summary>
    public (double Roll, double Pitch, double Yaw) RollPitchYaw()
    {
        var r = Rotation;
        var sinPitch = Math.Clamp(-r.X.Z, -1, 1);
        if (Math.Abs(sinPitch) > 1 - 1e-12)
        {
            return (0, Math.CopySign(Math.PI / 2, sinPitch), Math.Atan2(-r.Y.X, r.Y.Y));
        }

        return (Math.Atan2(r.Y.Z, r.Z.Z), Math.Asin(sinPitch), Math.Atan2(r.X.Y, r.X.X));
    }

    /// <summary>The frame whose z axis points along <paramref name="direction"/> (a cylinder's axis), placed at <paramref name="position"/>.</summary>
    public static UrdfFrame AlongZ(Vector3d position, Vector3d direction)
    {
        var u = direction.Normalized();
        var pitch = Math.Atan2(Math.Sqrt((u.X * u.X) + (u.Y * u.Y)), u.Z);
        var yaw = Math.Atan2(u.Y, u.X);
        return new UrdfFrame(position, Rotation3d.FromRollPitchYaw(0, pitch, yaw));
    }
}
