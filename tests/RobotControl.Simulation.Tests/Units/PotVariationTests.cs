using RobotControl.Bus.Protocol;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.Simulation.Units;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests.Units;

/// <summary>A unit's own pot curves (<see cref="VirtualRobotOptions.UnitVariationSeed"/>): drawn from a seed, within the bounds, and what the pots read.</summary>
public sealed class PotVariationTests
{
    [Fact]
    public void The_same_seed_gives_the_same_unit_and_another_seed_another()
    {
        using var a = Unit(seed: 7);
        using var b = Unit(seed: 7);
        using var c = Unit(seed: 8);
        Assert.Equal(a.Axes.Select(x => x.TruePot), b.Axes.Select(x => x.TruePot));
        Assert.All(a.Axes.Zip(c.Axes), p => Assert.NotEqual(p.First.TruePot, p.Second.TruePot));
        Assert.All(a.Axes, x => Assert.NotEqual(x.Config.Motor.Pot, x.TruePot));
    }

    [Fact]
    public void Without_a_seed_every_pot_follows_its_design_curve()
    {
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider());
        Assert.All(sim.Axes, x => Assert.Equal(x.Config.Motor.Pot, x.TruePot));
        Assert.All(sim.Axes, x => Assert.Equal(PotVariation.None, x.PotVariation));
    }

    [Fact]
    public void Every_variation_stays_within_the_bounds_and_uses_them()
    {
        var bounds = PotVariationBounds.Default;
        var drawn = Enumerable.Range(1, 200).SelectMany(seed => PotVariation.Draw(seed, 10, bounds)).ToList();
        Assert.All(drawn, v => Assert.True(v.IsWithin(bounds), v.ToString()));
        Assert.True(drawn.Max(v => Math.Abs(v.OffsetCounts)) > 0.9 * bounds.OffsetCounts);
        Assert.True(drawn.Max(v => Math.Abs(v.Gain)) > 0.9 * bounds.GainFraction);
        Assert.True(drawn.Max(v => Math.Abs(v.BowCounts)) > 0.9 * bounds.BowCounts);
        Assert.False(new PotVariation(bounds.OffsetCounts * 1.01, 0, 0).IsWithin(bounds));
    }

    [Fact]
    public void A_true_curve_moves_the_ends_by_the_offset_scales_the_span_and_adds_to_the_bow()
    {
        var design = VirtualLb.Lb.Modules.Modules[0].Motors[0].Pot;
        var truth = new PotVariation(50, 0.04, -10).Apply(design);
        Assert.Equal(design.AdcAtMin + 50, truth.AdcAtMin, 9);
        Assert.Equal((design.AdcAtMax - design.AdcAtMin) * 1.04, truth.AdcAtMax - truth.AdcAtMin, 9);
        Assert.Equal(design.BowCounts - 10, truth.BowCounts, 9);
        Assert.Equal((design.MinRad, design.MaxRad), (truth.MinRad, truth.MaxRad));
    }

    [Fact]
    public void The_pots_read_the_true_curve_not_the_design_curve()
    {
        using var sim = Unit(seed: 3);
        sim.Advance(TimeSpan.FromMilliseconds(5));
        var potRaw = ControlTable.Firmware["pot_raw"];
        var raw = new byte[potRaw.Size];
        var largestDesignGap = 0.0;
        foreach (var axis in sim.Axes)
        {
            sim.PeekTable(axis.Config.ModuleId, potRaw.At(axis.Config.Channel), raw);
            var reading = potRaw.Decode(raw);
            Assert.InRange(reading - axis.TruePot.Reading(axis.OutputAngleRad), -1, 1);
            largestDesignGap = Math.Max(largestDesignGap, Math.Abs(reading - axis.Config.Motor.Pot.Reading(axis.OutputAngleRad)));
        }

        Assert.True(largestDesignGap > 20, $"the pots read within {largestDesignGap:F1} counts of the design curves");
    }

    private static VirtualRobot Unit(int seed) =>
        new(VirtualLb.Lb, new ManualTimeProvider(), new VirtualRobotOptions { UnitVariationSeed = seed, PotNoiseCounts = 0 });
}
