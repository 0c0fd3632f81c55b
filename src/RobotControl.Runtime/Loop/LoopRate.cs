using System.Globalization;

namespace RobotControl.Runtime.Loop;

/// <summary>The control-loop rates the platform accepts, in one place for the loop and the graph files.</summary>
public static class LoopRate
{
    /// <summary>The lowest rate, Hz.</summary>
    public const double MinHz = 1;

    /// <summary>The highest rate, Hz.</summary>
    public const double MaxHz = 20_000;

    /// <summary>The range as messages write it: <c>1..20000</c>.</summary>
    public static string RangeText { get; } = string.Create(CultureInfo.InvariantCulture, $"{MinHz}..{MaxHz}");

    /// <summary>True for a finite rate within <see cref="MinHz"/>..<see cref="MaxHz"/>.</summary>
    public static bool IsValid(double rateHz) => double.IsFinite(rateHz) && rateHz >= MinHz && rateHz <= MaxHz;
}
