namespace RobotControl.Bench.Ik;

/// <summary>Solve rate and per-solve time statistics of one solver over one target set.</summary>
internal sealed record SolverStats(string Name, int Samples, double SolveRate, double MeanUs, double MedianUs, double P99Us, string Note)
{
    /// <summary>99.9th percentile of the per-solve times.</summary>
    public double P999Us { get; init; }

    /// <summary>The slowest solve.</summary>
    public double MaxUs { get; init; }

    /// <summary>Thread CPU time per solve over an untimed second pass (NaN if not measured).</summary>
    public double MeanCpuUs { get; init; } = double.NaN;

    public static SolverStats From(string name, IReadOnlyList<double> timesUs, int solved, string note = "")
    {
        var sorted = timesUs.Order().ToArray();
        var count = sorted.Length;
        return new SolverStats(
            name,
            count,
            count == 0 ? 0 : (double)solved / count,
            count == 0 ? 0 : sorted.Average(),
            Percentile(sorted, 0.5),
            Percentile(sorted, 0.99),
            note)
        {
            P999Us = Percentile(sorted, 0.999),
            MaxUs = count == 0 ? 0 : sorted[^1],
        };
    }

    public static double Percentile(double[] sorted, double p)
    {
        if (sorted.Length == 0)
        {
            return 0;
        }

        var rank = p * (sorted.Length - 1);
        var lo = (int)Math.Floor(rank);
        var hi = Math.Min(lo + 1, sorted.Length - 1);
        return sorted[lo] + ((rank - lo) * (sorted[hi] - sorted[lo]));
    }
}
