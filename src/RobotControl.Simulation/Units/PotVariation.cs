using RobotControl.Definitions.Model;

namespace RobotControl.Simulation.Units;

/// <summary>
/// How one unit's pot differs from its design curve: the true curve is the design's moved by
/// <see cref="OffsetCounts"/>, its span scaled by 1 + <see cref="Gain"/>, its bow changed by <see cref="BowCounts"/>.
/// </summary>
/// <param name="OffsetCounts">Added to both ends, ADC counts.</param>
/// <param name="Gain">Relative change of the span (0.03: 3 % more counts between the ends).</param>
/// <param name="BowCounts">Added to the bow at mid-range, ADC counts.</param>
public sealed record PotVariation(double OffsetCounts, double Gain, double BowCounts)
{
    /// <summary>No variation: the design curve is the true one.</summary>
    public static PotVariation None { get; } = new(0, 0, 0);

    /// <summary>The true curve of a pot designed as <paramref name="design"/> (same angles, other counts).</summary>
    public PotCalibration Apply(PotCalibration design)
    {
        ArgumentNullException.ThrowIfNull(design);
        if (this == None)
        {
            return design; // exactly the design, not the design rebuilt from its span
        }

        var atMin = design.AdcAtMin + OffsetCounts;
        var atMax = atMin + ((design.AdcAtMax - design.AdcAtMin) * (1 + Gain));
        return design with { AdcAtMin = atMin, AdcAtMax = atMax, BowCounts = design.BowCounts + BowCounts };
    }

    /// <summary>True when every part is within <paramref name="bounds"/>.</summary>
    public bool IsWithin(PotVariationBounds bounds)
    {
        ArgumentNullException.ThrowIfNull(bounds);
        return Math.Abs(OffsetCounts) <= bounds.OffsetCounts && Math.Abs(Gain) <= bounds.GainFraction && Math.Abs(BowCounts) <= bounds.BowCounts;
    }

    /// <summary>
    /// The variations of a unit's <paramref name="pots"/> pots (in the robot file's order of modules and motors),
    /// drawn uniformly within <paramref name="bounds"/> from <paramref name="seed"/>: the same seed gives the same unit.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException">A negative count.</exception>
    public static IReadOnlyList<PotVariation> Draw(int seed, int pots, PotVariationBounds bounds)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(pots);
        ArgumentNullException.ThrowIfNull(bounds);
#pragma warning disable CA5394 // a simulated unit, not security
        var random = new Random(seed);
        double Within(double bound) => ((2 * random.NextDouble()) - 1) * bound;
#pragma warning restore CA5394
        var drawn = new PotVariation[pots];
        for (var i = 0; i < pots; i++)
        {
            drawn[i] = new PotVariation(Within(bounds.OffsetCounts), Within(bounds.GainFraction), Within(bounds.BowCounts));
        }

        return drawn;
    }
}
