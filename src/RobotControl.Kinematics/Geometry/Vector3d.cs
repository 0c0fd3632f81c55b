using System.Runtime.CompilerServices;

namespace RobotControl.Kinematics.Geometry;

/// <summary>
/// A double-precision 3-vector value type for the allocation-free kinematics hot path (mm or unit axes).
/// Written here because no served package offers one: OpenTK.Mathematics is not served and MathNet's vectors are
/// heap objects (see docs/dependencies.md). Only the operations kinematics needs.
/// </summary>
/// <param name="X">X component.</param>
/// <param name="Y">Y component.</param>
/// <param name="Z">Z component.</param>
public readonly record struct Vector3d(double X, double Y, double Z)
{
    /// <summary>The zero vector.</summary>
    public static Vector3d Zero => default;

    /// <summary>Unit X.</summary>
    public static Vector3d UnitX => new(1, 0, 0);

    /// <summary>Unit Y.</summary>
    public static Vector3d UnitY => new(0, 1, 0);

    /// <summary>Unit Z.</summary>
    public static Vector3d UnitZ => new(0, 0, 1);

    /// <summary>Euclidean length.</summary>
    public double Length => Math.Sqrt(LengthSquared);

    /// <summary>Squared length.</summary>
    public double LengthSquared => (X * X) + (Y * Y) + (Z * Z);

    /// <summary>True when every component is finite.</summary>
    public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

    /// <summary>Component by index 0..2.</summary>
    public double this[int index] => index switch
    {
        0 => X,
        1 => Y,
        2 => Z,
        _ => throw new ArgumentOutOfRangeException(nameof(index)),
    };

    /// <summary>Sum.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator +(Vector3d a, Vector3d b) => new(a.X + b.X, a.Y + b.Y, a.Z + b.Z);

    /// <summary>Difference.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator -(Vector3d a, Vector3d b) => new(a.X - b.X, a.Y - b.Y, a.Z - b.Z);

    /// <summary>Negation.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator -(Vector3d a) => new(-a.X, -a.Y, -a.Z);

    /// <summary>Scaling.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator *(Vector3d a, double s) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Scaling.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator *(double s, Vector3d a) => new(a.X * s, a.Y * s, a.Z * s);

    /// <summary>Division by a scalar.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d operator /(Vector3d a, double s) => new(a.X / s, a.Y / s, a.Z / s);

    /// <summary>Dot product.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static double Dot(Vector3d a, Vector3d b) => (a.X * b.X) + (a.Y * b.Y) + (a.Z * b.Z);

    /// <summary>Cross product a × b.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static Vector3d Cross(Vector3d a, Vector3d b) =>
        new((a.Y * b.Z) - (a.Z * b.Y), (a.Z * b.X) - (a.X * b.Z), (a.X * b.Y) - (a.Y * b.X));

    /// <summary>Distance between two points.</summary>
    public static double Distance(Vector3d a, Vector3d b) => (a - b).Length;

    /// <summary>Unit vector in the same direction (the zero vector stays zero).</summary>
    public Vector3d Normalized()
    {
        var l = Length;
        return l > 0 ? this / l : Zero;
    }

    /// <summary>Adds. (Named alternative for operator +.)</summary>
    public static Vector3d Add(Vector3d left, Vector3d right) => left + right;

    /// <summary>Subtracts. (Named alternative for operator -.)</summary>
    public static Vector3d Subtract(Vector3d left, Vector3d right) => left - right;

    /// <summary>Negates. (Named alternative for unary operator -.)</summary>
    public static Vector3d Negate(Vector3d value) => -value;

    /// <summary>Scales. (Named alternative for operator *.)</summary>
    public static Vector3d Multiply(Vector3d left, double right) => left * right;

    /// <summary>Divides. (Named alternative for operator /.)</summary>
    public static Vector3d Divide(Vector3d left, double right) => left / right;
}
