namespace RobotControl.Kinematics.Geometry;

/// <summary>A rotation given by its three column axes (the rotated frame's x, y, z in the base frame).</summary>
/// <param name="X">First column: the frame's x axis.</param>
/// <param name="Y">Second column: the frame's y axis.</param>
/// <param name="Z">Third column: the frame's z axis.</param>
public readonly record struct Rotation3d(Vector3d X, Vector3d Y, Vector3d Z)
{
    /// <summary>The identity rotation.</summary>
    public static Rotation3d Identity => new(Vector3d.UnitX, Vector3d.UnitY, Vector3d.UnitZ);

    /// <summary>Column by index 0..2.</summary>
    public Vector3d this[int column] => column switch
    {
        0 => X,
        1 => Y,
        2 => Z,
        _ => throw new ArgumentOutOfRangeException(nameof(column)),
    };

    /// <summary>Element at (row, column).</summary>
    public double At(int row, int column) => this[column][row];

    /// <summary>Rotates a vector: R v.</summary>
    public Vector3d Apply(Vector3d v) => (X * v.X) + (Y * v.Y) + (Z * v.Z);

    /// <summary>Rotates a vector by the transpose: Rᵀ v.</summary>
    public Vector3d ApplyTransposed(Vector3d v) => new(Vector3d.Dot(X, v), Vector3d.Dot(Y, v), Vector3d.Dot(Z, v));

    /// <summary>Product a b.</summary>
    public static Rotation3d operator *(Rotation3d a, Rotation3d b) => new(a.Apply(b.X), a.Apply(b.Y), a.Apply(b.Z));

    /// <summary>Product a b. (Named alternative for operator *.)</summary>
    public static Rotation3d Multiply(Rotation3d left, Rotation3d right) => left * right;

    /// <summary>Transpose (the inverse of a rotation).</summary>
    public Rotation3d Transposed() =>
        new(new Vector3d(X.X, Y.X, Z.X), new Vector3d(X.Y, Y.Y, Z.Y), new Vector3d(X.Z, Y.Z, Z.Z));

    /// <summary>Rotation about X by <paramref name="angle"/> radians.</summary>
    public static Rotation3d AboutX(double angle)
    {
        var (s, c) = Math.SinCos(angle);
        return new(Vector3d.UnitX, new Vector3d(0, c, s), new Vector3d(0, -s, c));
    }

    /// <summary>Rotation about Y by <paramref name="angle"/> radians.</summary>
    public static Rotation3d AboutY(double angle)
    {
        var (s, c) = Math.SinCos(angle);
        return new(new Vector3d(c, 0, -s), Vector3d.UnitY, new Vector3d(s, 0, c));
    }

    /// <summary>Rotation about Z by <paramref name="angle"/> radians.</summary>
    public static Rotation3d AboutZ(double angle)
    {
        var (s, c) = Math.SinCos(angle);
        return new(new Vector3d(c, s, 0), new Vector3d(-s, c, 0), Vector3d.UnitZ);
    }

    /// <summary>Rotation about the unit axis <paramref name="axis"/> by <paramref name="angle"/> radians (Rodrigues).</summary>
    public static Rotation3d AboutAxis(Vector3d axis, double angle)
    {
        var (s, c) = Math.SinCos(angle);
        Vector3d Turn(Vector3d v) => (v * c) + (Vector3d.Cross(axis, v) * s) + (axis * (Vector3d.Dot(axis, v) * (1 - c)));
        return new(Turn(Vector3d.UnitX), Turn(Vector3d.UnitY), Turn(Vector3d.UnitZ));
    }

    /// <summary>Rotation from roll (about X), pitch (about Y), yaw (about Z), applied as Rz(yaw) Ry(pitch) Rx(roll).</summary>
    public static Rotation3d FromRollPitchYaw(double roll, double pitch, double yaw) => AboutZ(yaw) * AboutY(pitch) * AboutX(roll);

    /// <summary>Roll, pitch, yaw (inverse of <see cref="FromRollPitchYaw"/>).</summary>
    public (double Roll, double Pitch, double Yaw) ToRollPitchYaw()
    {
        var pitch = Math.Asin(Math.Clamp(-X.Z, -1, 1));
        var roll = Math.Atan2(Y.Z, Z.Z);
        var yaw = Math.Atan2(X.Y, X.X);
        return (roll, pitch, yaw);
    }
}

/// <summary>A rigid pose: position (mm) and orientation.</summary>
/// <param name="Position">Origin, mm.</param>
/// <param name="Rotation">Orientation.</param>
public readonly record struct Pose(Vector3d Position, Rotation3d Rotation);
