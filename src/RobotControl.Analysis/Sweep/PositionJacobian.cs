namespace RobotControl.Analysis.Sweep;

/// <summary>The 3 x m position rows of a geometric Jacobian restricted to the used joints, and Yoshikawa's manipulability.</summary>
internal static class PositionJacobian
{
    /// <summary>Copies rows vx, vy, vz of the 6 x n Jacobian <paramref name="full"/>, columns <paramref name="used"/>, into 3 x m <paramref name="target"/>.</summary>
    public static void Extract(ReadOnlySpan<double> full, int jointCount, IReadOnlyList<int> used, Span<double> target)
    {
        var m = used.Count;
        for (var r = 0; r < 3; r++)
        {
            for (var c = 0; c < m; c++)
            {
                target[(r * m) + c] = full[(r * jointCount) + used[c]];
            }
        }
    }

    /// <summary>w = sqrt(det(J Jᵀ)) of a 3 x m row-major <paramref name="j"/> (mm³ per rad³ for J in mm/rad).</summary>
    public static double Manipulability(ReadOnlySpan<double> j, int m)
    {
        Span<double> g = stackalloc double[9];
        for (var r = 0; r < 3; r++)
        {
            for (var c = r; c < 3; c++)
            {
                var sum = 0.0;
                for (var i = 0; i < m; i++)
                {
                    sum += j[(r * m) + i] * j[(c * m) + i];
                }

                g[(r * 3) + c] = sum;
                g[(c * 3) + r] = sum;
            }
        }

        var det = (g[0] * ((g[4] * g[8]) - (g[5] * g[7])))
                  - (g[1] * ((g[3] * g[8]) - (g[5] * g[6])))
                  + (g[2] * ((g[3] * g[7]) - (g[4] * g[6])));
        return Math.Sqrt(Math.Max(det, 0.0));
    }
}
