using RobotControl.Kinematics.Geometry;

namespace RobotControl.Kinematics.Forward;

/// <summary>
/// Yoshikawa's manipulability w = sqrt(det(J Jᵀ)) over the position rows of the geometric Jacobian (docs/algorithms.md),
/// in mm³ for three or more joints. J Jᵀ is 3 x 3 whatever the joint count, so its determinant is written out in
/// closed form: allocation-free, for the control loop and the capability sweeps.
/// </summary>
public static class Manipulability
{
    /// <summary>
    /// w of a row-major Jacobian with <paramref name="columns"/> columns whose first three rows are the position rows
    /// (a 3 x n position Jacobian or the 6 x n geometric Jacobian of <see cref="ChainState.Jacobian"/>).
    /// </summary>
    public static double FromJacobian(ReadOnlySpan<double> jacobian, int columns)
    {
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(columns);
        if (jacobian.Length < 3 * columns)
        {
            throw new ArgumentException($"needs at least 3 x {columns} values", nameof(jacobian));
        }

        var gram = default(Gram);
        for (var j = 0; j < columns; j++)
        {
            gram.Add(new Vector3d(jacobian[j], jacobian[columns + j], jacobian[(2 * columns) + j]));
        }

        return gram.SquareRootOfDeterminant();
    }

    /// <summary>w over every joint of the chain at the state's last <see cref="ChainState.Update"/>.</summary>
    public static double Of(ChainState state)
    {
        ArgumentNullException.ThrowIfNull(state);
        var gram = default(Gram);
        var end = state.ToolPosition;
        for (var j = 0; j < state.Chain.JointCount; j++)
        {
            gram.Add(Vector3d.Cross(state.JointAxis(j), end - state.JointOrigin(j)));
        }

        return gram.SquareRootOfDeterminant();
    }

    /// <summary>w over the given joints only (e.g. the robot's position joints), the others held fixed.</summary>
    public static double Of(ChainState state, ReadOnlySpan<int> joints)
    {
        ArgumentNullException.ThrowIfNull(state);
        var gram = default(Gram);
        var end = state.ToolPosition;
        foreach (var j in joints)
        {
            gram.Add(Vector3d.Cross(state.JointAxis(j), end - state.JointOrigin(j)));
        }

        return gram.SquareRootOfDeterminant();
    }

    /// <summary>det of a symmetric 3 x 3 matrix given by its upper triangle.</summary>
    internal static double SymmetricDeterminant(double a00, double a01, double a02, double a11, double a12, double a22) =>
        (a00 * ((a11 * a22) - (a12 * a12))) - (a01 * ((a01 * a22) - (a12 * a02))) + (a02 * ((a01 * a12) - (a11 * a02)));

    /// <summary>The 3 x 3 Gram matrix J Jᵀ = Σ v vᵀ accumulated column by column (upper triangle).</summary>
    private struct Gram
    {
        private double _xx;
        private double _xy;
        private double _xz;
        private double _yy;
        private double _yz;
        private double _zz;

        public void Add(Vector3d v)
        {
            _xx += v.X * v.X;
            _xy += v.X * v.Y;
            _xz += v.X * v.Z;
            _yy += v.Y * v.Y;
            _yz += v.Y * v.Z;
            _zz += v.Z * v.Z;
        }

        // Rounding can leave a tiny negative determinant at a singularity; w is 0 there.
        public readonly double SquareRootOfDeterminant() =>
            Math.Sqrt(Math.Max(0.0, SymmetricDeterminant(_xx, _xy, _xz, _yy, _yz, _zz)));
    }
}
