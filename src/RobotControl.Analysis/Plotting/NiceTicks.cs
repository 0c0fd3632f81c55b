namespace RobotControl.Analysis.Plotting;

/// <summary>Axis tick positions at 1, 2 or 5 times a power of ten.</summary>
internal static class NiceTicks
{
    /// <summary>Ticks inside [min, max], about <paramref name="target"/> of them.</summary>
    public static IReadOnlyList<double> For(double min, double max, int target)
    {
        if (!(max > min))
        {
            return [min];
        }

        var step = Step((max - min) / Math.Max(1, target));
        var first = Math.Ceiling((min / step) - 1e-9) * step;
        var ticks = new List<double>();
        for (var v = first; v <= max + (1e-9 * step); v += step)
        {
            ticks.Add(Math.Abs(v) < 1e-12 * step ? 0 : v);
        }

        return ticks;
    }

    /// <summary>Label text with as many decimals as the tick spacing needs.</summary>
    public static string Format(double value, IReadOnlyList<double> ticks)
    {
        var spacing = ticks.Count > 1 ? Math.Abs(ticks[1] - ticks[0]) : Math.Abs(value);
        var decimals = spacing >= 1 || spacing == 0 ? 0 : (int)Math.Ceiling(-Math.Log10(spacing) - 1e-9);
        return value.ToString("F" + Math.Clamp(decimals, 0, 6), System.Globalization.CultureInfo.InvariantCulture);
    }

    private static double Step(double raw)
    {
        var magnitude = Math.Pow(10, Math.Floor(Math.Log10(raw)));
        var normalised = raw / magnitude;
        var nice = normalised < 1.5 ? 1 : normalised < 3 ? 2 : normalised < 7 ? 5 : 10;
        return nice * magnitude;
    }
}
