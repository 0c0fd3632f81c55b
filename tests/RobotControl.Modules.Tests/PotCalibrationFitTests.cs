using RobotControl.Definitions.Model;
using RobotControl.TestSupport;
using Xunit.Abstractions;

namespace RobotControl.Modules.Tests;

/// <summary>
/// The fit of a module's pot table to measured readings, against known curves: the design curve and curves moved by an
/// offset, a gain and a bow (each at and beyond the simulator's unit-variation bounds, and together). The fitted table
/// must give every position of the joint's range from the true curve's reading within a bound derived from the table's
/// point spacing h: a curve r(x) with |r''| ≤ M is off its piecewise-linear interpolant by at most M·h²/8 ADC counts;
/// for the pots' curve r = a + (b - a)·u + bow·sin(π·u) over L counts, M = |bow|·π²/L², and a count of reading is
/// worth at most 1/min|r'| = L/(|b - a| - π·|bow|) Hall counts. Add a count of reading (the table's readings and the
/// sampled one are rounded to integers, half a count each) and one Hall count (the firmware's integer division).
/// </summary>
public sealed class PotCalibrationFitTests(ITestOutputHelper output)
{
    public static TheoryData<string, double, double, double> Curves => new()
    {
        { "design", 0, 0, 0 },
        { "offset +80", 80, 0, 0 },
        { "offset -80", -80, 0, 0 },
        { "gain +5 %", 0, 0.05, 0 },
        { "gain -5 %", 0, -0.05, 0 },
        { "bow +30", 0, 0, 30 },
        { "bow -60", 0, 0, -60 },
        { "all at once", -80, 0.05, 30 },
    };

    [Theory]
    [MemberData(nameof(Curves))]
    public void The_fitted_table_gives_the_true_curves_positions_within_the_interpolation_bound_of_its_spacing(string name, double offset, double gain, double bow)
    {
        var robot = VirtualLb.Lb;
        foreach (var module in robot.Modules.Modules)
        {
            foreach (var motor in module.Motors)
            {
                var config = new MotorConfig(robot, module, motor);
                var design = motor.Pot;
                var atMin = design.AdcAtMin + offset;
                var truth = design with { AdcAtMin = atMin, AdcAtMax = atMin + ((design.AdcAtMax - design.AdcAtMin) * (1 + gain)), BowCounts = design.BowCounts + bow };
                var (pos0, step) = PotCalibrationFit.Span(config);
                var end = pos0 + ((PotCalibrationTable.MaxPoints - 1) * step);
                var samples = Enumerable.Range(0, 2001).Select(i => pos0 + ((end - pos0) * i / 2000))
                    .Select(x => new PotSample(x, Reading(truth, config, x))).ToList();

                var table = PotCalibrationFit.Fit(samples, pos0, step);

                Assert.Equal((PotCalibrationTable.MaxPoints, pos0, step), (table.Count, table.Pos0, table.Step));
                var spanCounts = config.ToCounts(truth.MaxRad) - config.ToCounts(truth.MinRad);
                var curvature = Math.Abs(truth.BowCounts) * Math.PI * Math.PI / ((double)spanCounts * spanCounts);
                var countsPerReading = Math.Abs(spanCounts) / (Math.Abs(truth.AdcAtMax - truth.AdcAtMin) - (Math.PI * Math.Abs(truth.BowCounts)));
                var bound = (((curvature * step * step / 8) + 1) * countsPerReading) + 1;
                var worst = samples.Max(s => Math.Abs(table.PositionAt(s.Raw) - s.Position));
                output.WriteLine($"{name,-12} {config.FullName,-24} step {step,6} counts: worst {worst,4} counts = {config.ToRadians(worst) * 180 / Math.PI:F3} deg, bound {bound:F1} counts");
                Assert.True(worst <= bound, $"{name}, {config.FullName}: the fitted table is {worst} counts off, bound {bound:F1}");
            }
        }
    }

    [Fact]
    public void Samples_away_from_the_ends_are_extrapolated_and_with_noise_the_design_curves_table_is_reproduced()
    {
        var robot = VirtualLb.Lb;
        var module = robot.Modules.Modules[0];
        var config = new MotorConfig(robot, module, module.Motors[2]);
        var (pos0, step) = PotCalibrationFit.Span(config);
        var random = new Random(5);
        // Three quarters of the first and last segments measured, readings noisy by up to 2 counts.
        var samples = Enumerable.Range(0, 4001).Select(i => pos0 + (step / 4) + (((6 * step) + (step / 2)) * i / 4000))
            .Select(x => new PotSample(x, Reading(config.Motor.Pot, config, x) + random.Next(-2, 3))).ToList();

        var table = PotCalibrationFit.Fit(samples, pos0, step);

        for (var k = 0; k < table.Count; k++)
        {
            var expected = config.Motor.Pot.Reading(config.ToRadians(pos0 + (k * step)));
            Assert.InRange(table.Raw[k], expected - 4, expected + 4);
        }
    }

    [Fact]
    public void A_range_not_moved_through_or_a_flat_pot_is_refused_naming_the_points()
    {
        var robot = VirtualLb.Lb;
        var config = new MotorConfig(robot, robot.Modules.Modules[1], robot.Modules.Modules[1].Motors[0]);
        var (pos0, step) = PotCalibrationFit.Span(config);
        var half = Enumerable.Range(0, 500).Select(i => pos0 + (3 * step * i / 500)).Select(x => new PotSample(x, Reading(config.Motor.Pot, config, x))).ToList();
        var shortRange = Assert.Throws<ArgumentException>(() => PotCalibrationFit.Fit(half, pos0, step));
        Assert.Contains("between calibration points 3 and 4", shortRange.Message, StringComparison.Ordinal);
        Assert.Contains("the joint did not move through its range", shortRange.Message, StringComparison.Ordinal);

        var flat = Enumerable.Range(0, 700).Select(i => pos0 + (7 * step * i / 700)).Select(x => new PotSample(x, 2000)).ToList();
        var refused = Assert.Throws<ArgumentException>(() => PotCalibrationFit.Fit(flat, pos0, step));
        Assert.Contains("not strictly monotonic", refused.Message, StringComparison.Ordinal);
    }

    private static int Reading(PotCalibration curve, MotorConfig config, long counts) => (int)Math.Round(curve.Reading(config.ToRadians(counts)));
}
