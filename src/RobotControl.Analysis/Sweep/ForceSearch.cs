namespace RobotControl.Analysis.Sweep;

/// <summary>
/// The reference design's force search: the largest F on the grid 30.0, 29.9, ..., 0.1 N (k / 10 N, k = 300..1;
/// 0 when none) with |g_i| · F ≤ T_i for every joint i, where g_i is the Jacobian entry of the force axis (mm/rad)
/// and T_i the holding torque (mNm), so F is in N. The feasible set is the interval [0, min_i T_i / |g_i|], so the
/// answer is that bound quantised down to the grid; <see cref="Largest"/> computes it directly and confirms the
/// neighbouring grid points with the same floating-point test the step-down search uses, so both agree exactly.
/// </summary>
internal static class ForceSearch
{
    /// <summary>The search starts here, N.</summary>
    public const double MaxForceN = 30.0;

    /// <summary>Grid points per newton (0.1 N steps).</summary>
    public const int StepsPerNewton = 10;

    private const int MaxStep = 300;

    /// <summary>The largest feasible grid force, computed from the bound.</summary>
    public static double Largest(ReadOnlySpan<double> gains, ReadOnlySpan<double> limits)
    {
        var bound = double.PositiveInfinity;
        for (var i = 0; i < gains.Length; i++)
        {
            var g = Math.Abs(gains[i]);
            if (g > 0)
            {
                bound = Math.Min(bound, limits[i] / g);
            }
        }

        var k = bound >= MaxForceN ? MaxStep : (int)Math.Clamp(Math.Floor(bound * StepsPerNewton), 0, MaxStep);
        while (k < MaxStep && Feasible(ValueAt(k + 1), gains, limits))
        {
            k++;
        }

        while (k > 0 && !Feasible(ValueAt(k), gains, limits))
        {
            k--;
        }

        return ValueAt(k);
    }

    /// <summary>The reference design's step-down search (kept to check <see cref="Largest"/> against).</summary>
    public static double StepDown(ReadOnlySpan<double> gains, ReadOnlySpan<double> limits)
    {
        for (var k = MaxStep; k > 0; k--)
        {
            if (Feasible(ValueAt(k), gains, limits))
            {
                return ValueAt(k);
            }
        }

        return 0.0;
    }

    private static double ValueAt(int k) => (double)k / StepsPerNewton;

    private static bool Feasible(double force, ReadOnlySpan<double> gains, ReadOnlySpan<double> limits)
    {
        for (var i = 0; i < gains.Length; i++)
        {
            if (Math.Abs(gains[i]) * force > limits[i])
            {
                return false;
            }
        }

        return true;
    }
}
