using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Drivetrain;

/// <summary>
/// Coupling-aware limits: the actuators turn s = C q (e.g. sun gears phi1 ± phi2), so the speed and torque limits
/// apply to s and to the actuator torques tau_act with tau_joint = Cᵀ tau_act (virtual work). Restricted to the
/// joints an analysis uses, q̇ = C⁻¹ u with |u_k| ≤ Omega_k, and tau_act = C⁻ᵀ Jᵀ f; both read the matrix
/// K = J C⁻¹ (3 x m), so velocity and force take the same form as the reference method with K in place of J.
/// </summary>
internal sealed class CoupledDriveModel
{
    private readonly double[] _inverse;

    private CoupledDriveModel(int size, double[] inverse, double[] speed, double[] torque, string[] names)
    {
        Size = size;
        _inverse = inverse;
        SpeedRadPerS = speed;
        TorqueMNm = torque;
        ActuatorNames = names;
    }

    /// <summary>Number of used joints (and actuators).</summary>
    public int Size { get; }

    /// <summary>Output speed per actuator (in the order of the inverse's columns), rad/s.</summary>
    public double[] SpeedRadPerS { get; }

    /// <summary>Output torque per actuator, mNm.</summary>
    public double[] TorqueMNm { get; }

    /// <summary>Actuator names in column order.</summary>
    public string[] ActuatorNames { get; }

    /// <summary>
    /// Builds the model over <paramref name="usedJoints"/>: the actuators with a non-zero coupling on any used joint
    /// must be exactly as many as the joints and their coupling matrix invertible.
    /// </summary>
    public static CoupledDriveModel Create(RobotDefinition robot, IReadOnlyList<int> usedJoints, IReadOnlyList<DrivetrainPerformance> performance)
    {
        var m = usedJoints.Count;
        var actuators = Enumerable.Range(0, robot.Actuators.Count)
            .Where(k => usedJoints.Any(j => robot.Actuators[k].Coupling[j] != 0))
            .ToArray();
        if (actuators.Length != m)
        {
            throw new ArgumentException(
                $"{robot.Name}: coupling-aware analysis needs as many actuators as used joints ({m}); " +
                $"{actuators.Length} actuators couple into them");
        }

        var c = new double[m * m];
        for (var r = 0; r < m; r++)
        {
            for (var col = 0; col < m; col++)
            {
                c[(r * m) + col] = robot.Actuators[actuators[r]].Coupling[usedJoints[col]];
            }
        }

        var inverse = Invert(c, m)
            ?? throw new ArgumentException($"{robot.Name}: the coupling matrix of the used joints is singular");
        return new CoupledDriveModel(
            m,
            inverse,
            actuators.Select(k => performance[k].SpeedRadPerS).ToArray(),
            actuators.Select(k => performance[k].TorqueMNm).ToArray(),
            actuators.Select(k => robot.Actuators[k].Name).ToArray());
    }

    /// <summary>K = J C⁻¹ for the 3 x m position Jacobian <paramref name="j"/> (row-major), written to <paramref name="k"/>.</summary>
    public void MapJacobian(ReadOnlySpan<double> j, Span<double> k)
    {
        var m = Size;
        for (var r = 0; r < 3; r++)
        {
            for (var col = 0; col < m; col++)
            {
                var sum = 0.0;
                for (var i = 0; i < m; i++)
                {
                    sum += j[(r * m) + i] * _inverse[(i * m) + col];
                }

                k[(r * m) + col] = sum;
            }
        }
    }

    /// <summary>Gauss-Jordan inverse with partial pivoting; null when singular.</summary>
    private static double[]? Invert(double[] matrix, int n)
    {
        var a = (double[])matrix.Clone();
        var inv = new double[n * n];
        for (var i = 0; i < n; i++)
        {
            inv[(i * n) + i] = 1;
        }

        for (var col = 0; col < n; col++)
        {
            var pivot = col;
            for (var r = col + 1; r < n; r++)
            {
                if (Math.Abs(a[(r * n) + col]) > Math.Abs(a[(pivot * n) + col]))
                {
                    pivot = r;
                }
            }

            if (Math.Abs(a[(pivot * n) + col]) < 1e-12)
            {
                return null;
            }

            SwapRows(a, n, col, pivot);
            SwapRows(inv, n, col, pivot);
            var scale = 1.0 / a[(col * n) + col];
            for (var c = 0; c < n; c++)
            {
                a[(col * n) + c] *= scale;
                inv[(col * n) + c] *= scale;
            }

            for (var r = 0; r < n; r++)
            {
                var factor = a[(r * n) + col];
                if (r == col || factor == 0)
                {
                    continue;
                }

                for (var c = 0; c < n; c++)
                {
                    a[(r * n) + c] -= factor * a[(col * n) + c];
                    inv[(r * n) + c] -= factor * inv[(col * n) + c];
                }
            }
        }

        return inv;
    }

    private static void SwapRows(double[] m, int n, int r1, int r2)
    {
        if (r1 == r2)
        {
            return;
        }

        for (var c = 0; c < n; c++)
        {
            (m[(r1 * n) + c], m[(r2 * n) + c]) = (m[(r2 * n) + c], m[(r1 * n) + c]);
        }
    }
}
