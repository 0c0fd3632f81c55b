namespace RobotControl.Simulation.Units;

/// <summary>
/// How far a unit's pot may differ from the robot file's design curve (<c>adc_at_min</c>, <c>adc_at_max</c>,
/// <c>bow_counts</c>): the one place these bounds are set (docs/bring-up.md, "A virtual robot from the factory", states
/// them). Each pot's offset, gain and bow are drawn uniformly within ±the bound.
/// </summary>
/// <param name="OffsetCounts">Shift of the whole curve, ADC counts (wiper and divider tolerance).</param>
/// <param name="GainFraction">Relative change of the span <c>adc_at_max - adc_at_min</c> (track resistance, reference).</param>
/// <param name="BowCounts">Added to the bow at mid-range, ADC counts (track linearity).</param>
public sealed record PotVariationBounds(double OffsetCounts, double GainFraction, double BowCounts)
{
    /// <summary>The bounds of <c>--unit-variation</c>: ±80 counts offset, ±5 % gain, ±30 counts bow.</summary>
    public static PotVariationBounds Default { get; } = new(80, 0.05, 30);
}
