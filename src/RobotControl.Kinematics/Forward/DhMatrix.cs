using MathNet.Numerics.LinearAlgebra;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Forward;

/// <summary>
/// Forward kinematics as the plain product of 4 x 4 homogeneous DH transforms (docs/robots.md):
/// T(i-1 -> i) = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i). Built from MathNet matrices, one elementary transform at a
/// time, so it is an independent check of the forward recursion in <see cref="ChainState"/>. Allocates; not for the
/// control loop.
/// </summary>
public static class DhMatrix
{
    /// <summary>The transform of one DH row for joint value <paramref name="jointRad"/> (ignored for a fixed row).</summary>
    public static Matrix<double> RowTransform(DhRow row, double jointRad)
    {
        ArgumentNullException.ThrowIfNull(row);
        var theta = row.ThetaOffsetRad + (row.IsFixed ? 0.0 : jointRad);
        return RotationZ(theta) * Translation(0, 0, row.DMm) * Translation(row.AMm, 0, 0) * RotationX(row.AlphaRad);
    }

    /// <summary>Base -> tool transform: the product of every row's transform for joint vector <paramref name="q"/> (radians).</summary>
    public static Matrix<double> ToolTransform(IReadOnlyList<DhRow> rows, ReadOnlySpan<double> q)
    {
        ArgumentNullException.ThrowIfNull(rows);
        var t = Matrix<double>.Build.DenseIdentity(4);
        foreach (var row in rows)
        {
            if (!row.IsFixed && row.JointIndex >= q.Length)
            {
                throw new ArgumentException($"joint vector has {q.Length} values; a DH row needs joint {row.JointIndex}", nameof(q));
            }

            t *= RowTransform(row, row.IsFixed ? 0.0 : q[row.JointIndex]);
        }

        return t;
    }

    /// <summary>Base -> tool transform of <paramref name="chain"/> for joint vector <paramref name="q"/> (radians).</summary>
    public static Matrix<double> ToolTransform(KinematicChain chain, ReadOnlySpan<double> q)
    {
        ArgumentNullException.ThrowIfNull(chain);
        return ToolTransform(chain.Rows, q);
    }

    /// <summary>The tool pose (position mm, rotation) held in a homogeneous transform.</summary>
    public static Pose ToPose(Matrix<double> transform)
    {
        ArgumentNullException.ThrowIfNull(transform);
        if (transform.RowCount != 4 || transform.ColumnCount != 4)
        {
            throw new ArgumentException("a homogeneous transform is 4 x 4", nameof(transform));
        }

        Vector3d Column(int c) => new(transform[0, c], transform[1, c], transform[2, c]);
        return new Pose(Column(3), new Rotation3d(Column(0), Column(1), Column(2)));
    }

    /// <summary>Rotation about z as a homogeneous transform.</summary>
    public static Matrix<double> RotationZ(double angle)
    {
        var (s, c) = Math.SinCos(angle);
        return Matrix<double>.Build.DenseOfArray(new[,]
        {
            { c, -s, 0, 0 },
            { s, c, 0, 0 },
            { 0, 0, 1, 0 },
            { 0, 0, 0, 1 },
        });
    }

    /// <summary>Rotation about x as a homogeneous transform.</summary>
    public static Matrix<double> RotationX(double angle)
    {
        var (s, c) = Math.SinCos(angle);
        return Matrix<double>.Build.DenseOfArray(new[,]
        {
            { 1, 0, 0, 0 },
            { 0, c, -s, 0 },
            { 0, s, c, 0 },
            { 0, 0, 0, 1 },
        });
    }

    /// <summary>Pure translation as a homogeneous transform.</summary>
    public static Matrix<double> Translation(double x, double y, double z)
    {
        var t = Matrix<double>.Build.DenseIdentity(4);
        t[0, 3] = x;
        t[1, 3] = y;
        t[2, 3] = z;
        return t;
    }
}
