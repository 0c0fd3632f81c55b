using System.Text.Json.Serialization;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>One target set's figures for the JSON: the distribution (wall and CPU), the slowest targets and every failure.</summary>
internal sealed record IkSetReport
{
    [JsonPropertyName("set")]
    public required string Set { get; init; }

    [JsonPropertyName("samples")]
    public required int Samples { get; init; }

    [JsonPropertyName("solved")]
    public required int Solved { get; init; }

    [JsonPropertyName("solve_rate")]
    public required double SolveRate { get; init; }

    [JsonPropertyName("wall_us")]
    public required Distribution Wall { get; init; }

    [JsonPropertyName("cpu_us")]
    public required Distribution Cpu { get; init; }

    [JsonPropertyName("iterations")]
    public required Distribution Iterations { get; init; }

    [JsonPropertyName("statuses")]
    public required Dictionary<string, int> Statuses { get; init; }

    [JsonPropertyName("bytes_per_solve")]
    public required double BytesPerSolve { get; init; }

    [JsonPropertyName("worst")]
    public required IReadOnlyList<IkCase> Worst { get; init; }

    [JsonPropertyName("failures")]
    public required IReadOnlyList<IkCase> Failures { get; init; }

    public static IkSetReport From(OurRandomRun run, int worstCount)
    {
        var chain = run.Set.Chain;
        var seed = new double[chain.JointCount];
        chain.MidRange(seed);
        var count = run.TimesUs.Length;
        var worst = Enumerable.Range(0, count)
            .OrderByDescending(i => run.TimesUs[i])
            .Take(worstCount)
            .Select(i => IkCase.From(run, i, seed))
            .ToList();
        var failures = Enumerable.Range(0, count)
            .Where(i => !run.Solved[i])
            .Select(i => IkCase.From(run, i, seed))
            .ToList();
        var solved = count - failures.Count;
        return new IkSetReport
        {
            Set = run.Set.Name,
            Samples = count,
            Solved = solved,
            SolveRate = (double)solved / count,
            Wall = Distribution.Of(run.TimesUs),
            Cpu = Distribution.Of(run.CpuUs),
            Iterations = Distribution.Of(run.Iterations.Select(i => (double)i).ToArray()),
            Statuses = run.Status.GroupBy(s => s.ToString()).ToDictionary(g => g.Key, g => g.Count()),
            BytesPerSolve = run.BytesPerSolve,
            Worst = worst,
            Failures = failures,
        };
    }

    /// <summary>Mean, median, p99, p99.9 and maximum.</summary>
    internal sealed record Distribution(
        [property: JsonPropertyName("mean")] double Mean,
        [property: JsonPropertyName("median")] double Median,
        [property: JsonPropertyName("p99")] double P99,
        [property: JsonPropertyName("p99_9")] double P999,
        [property: JsonPropertyName("max")] double Max)
    {
        public static Distribution Of(double[] values)
        {
            var sorted = values.Where(double.IsFinite).Order().ToArray();
            return sorted.Length == 0
                ? new Distribution(double.NaN, double.NaN, double.NaN, double.NaN, double.NaN)
                : new Distribution(sorted.Average(), SolverStats.Percentile(sorted, 0.5), SolverStats.Percentile(sorted, 0.99),
                    SolverStats.Percentile(sorted, 0.999), sorted[^1]);
        }
    }
}
