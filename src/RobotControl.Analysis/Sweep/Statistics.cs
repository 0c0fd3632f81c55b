namespace RobotControl.Analysis.Sweep;

/// <summary>Mean, minimum and maximum of a map.</summary>
/// <param name="Mean">Arithmetic mean over the points.</param>
/// <param name="Min">Smallest value.</param>
/// <param name="Max">Largest value.</param>
public readonly record struct Statistics(double Mean, double Min, double Max)
{
    /// <summary>Statistics of <paramref name="values"/> (at least one).</summary>
    public static Statistics Of(IReadOnlyList<double> values)
    {
        ArgumentNullException.ThrowIfNull(values);
        if (values.Count == 0)
        {
            throw new ArgumentException("no values", nameof(values));
        }

        double sum = 0, min = double.PositiveInfinity, max = double.NegativeInfinity;
        foreach (var v in values)
        {
            sum += v;
            min = Math.Min(min, v);
            max = Math.Max(max, v);
        }

        return new Statistics(sum / values.Count, min, max);
    }
}
