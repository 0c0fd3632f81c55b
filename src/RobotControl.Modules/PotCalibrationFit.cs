using System.Globalization;

namespace RobotControl.Modules;

/// <summary>One pot reading taken with the Hall position it was read at (counts at the axis output, absolute).</summary>
/// <param name="Position">Hall counts, in the frame the calibration table is in.</param>
/// <param name="Raw">The pot's ADC reading.</param>
public readonly record struct PotSample(long Position, int Raw);

/// <summary>
/// Fits the multi-point table a module keeps (<see cref="PotCalibrationTable"/>) to measured pot readings: the
/// piecewise-linear curve through <see cref="PotCalibrationTable.MaxPoints"/> points evenly spaced in Hall counts that
/// is closest to the samples (least squares; the end segments continue as straight lines, so samples just beyond the
/// ends count and a range measured a little short of the ends is extrapolated). Between two points the firmware
/// interpolates linearly (<see cref="PotCalibrationTable.PositionAt"/>), so for a true curve whose second derivative is
/// at most M the table is off by at most about M·Step²/8 ADC counts (the interpolation error of the spacing).
/// </summary>
public static class PotCalibrationFit
{
    /// <summary>A segment must be measured over at least this fraction of its span (else the fit is refused).</summary>
    public const double MinimumCoverage = 0.25;

    /// <summary>
    /// The points of <paramref name="config"/>'s table: from the low end to the high end of the range the joint moves
    /// through (its limits) that the pot's calibrated range also covers, in Hall counts.
    /// </summary>
    /// <exception cref="ArgumentException">The pot's range and the motion range do not overlap.</exception>
    public static (long Pos0, long Step) Span(MotorConfig config)
    {
        ArgumentNullException.ThrowIfNull(config);
        var pot = config.Motor.Pot;
        var low = Math.Max(config.OutputMinRad, Math.Min(pot.MinRad, pot.MaxRad));
        var high = Math.Min(config.OutputMaxRad, Math.Max(pot.MinRad, pot.MaxRad));
        if (!(high > low))
        {
            throw new ArgumentException($"{config.FullName}: the pot's calibrated range does not overlap the joint's range");
        }

        var pos0 = config.ToCounts(low);
        var step = (long)Math.Floor((config.ToCounts(high) - pos0) / (double)(PotCalibrationTable.MaxPoints - 1));
        return (pos0, step);
    }

    /// <summary>The table (<see cref="PotCalibrationTable.MaxPoints"/> points at <paramref name="pos0"/> + k·<paramref name="step"/>) closest to <paramref name="samples"/>.</summary>
    /// <exception cref="ArgumentException">
    /// A segment between two points was not measured over <see cref="MinimumCoverage"/> of its span, or the fitted
    /// readings are not strictly monotonic or leave the ADC range (the message says which point and why).
    /// </exception>
    public static PotCalibrationTable Fit(IReadOnlyList<PotSample> samples, long pos0, long step)
    {
        ArgumentNullException.ThrowIfNull(samples);
        ArgumentOutOfRangeException.ThrowIfLessThan(step, 1);
        var n = PotCalibrationTable.MaxPoints;
        var a = new double[n, n];
        var b = new double[n];
        var low = Enumerable.Repeat(double.PositiveInfinity, n - 1).ToArray();
        var high = Enumerable.Repeat(double.NegativeInfinity, n - 1).ToArray();
        foreach (var s in samples)
        {
            var u = (s.Position - pos0) / (double)step;
            var i = Math.Clamp((int)Math.Floor(u), 0, n - 2);
            var t = u - i;
            var (w0, w1) = (1 - t, t);
            a[i, i] += w0 * w0;
            a[i, i + 1] += w0 * w1;
            a[i + 1, i] += w0 * w1;
            a[i + 1, i + 1] += w1 * w1;
            b[i] += w0 * s.Raw;
            b[i + 1] += w1 * s.Raw;
            low[i] = Math.Min(low[i], Math.Clamp(t, 0, 1));
            high[i] = Math.Max(high[i], Math.Clamp(t, 0, 1));
        }

        for (var i = 0; i < n - 1; i++)
        {
            var covered = high[i] - low[i];
            if (!(covered >= MinimumCoverage))
            {
                throw new ArgumentException(string.Create(CultureInfo.InvariantCulture, $"between calibration points {i} and {i + 1} (counts {pos0 + (i * step)}..{pos0 + ((i + 1) * step)}) only {Math.Max(covered, 0) * 100:F0} % was measured ({samples.Count} samples in all); the joint did not move through its range"));
            }
        }

        var raw = Solve(a, b).Select(r => (long)Math.Round(r)).ToArray();
        var rising = raw[^1] > raw[0];
        for (var k = 0; k < n; k++)
        {
            if (raw[k] < 0 || raw[k] > Definitions.Model.PotCalibration.AdcFullScale)
            {
                throw new ArgumentException(string.Create(CultureInfo.InvariantCulture, $"calibration point {k} fits a pot reading of {raw[k]}, outside the ADC's 0..{Definitions.Model.PotCalibration.AdcFullScale}: check the pot's wiring"));
            }

            if (k > 0 && (raw[k] > raw[k - 1]) != rising || (k > 0 && raw[k] == raw[k - 1]))
            {
                throw new ArgumentException(string.Create(CultureInfo.InvariantCulture, $"the pot readings fitted at points {k - 1} and {k} ({raw[k - 1]}, {raw[k]}) are not strictly monotonic: the pot is flat or reverses there (a worn or slipping pot)"));
            }
        }

        return new PotCalibrationTable(n, pos0, step, raw);
    }

    /// <summary>Solves the (symmetric, positive definite when every segment is measured) normal equations by Gaussian elimination.</summary>
    private static double[] Solve(double[,] a, double[] b)
    {
        var n = b.Length;
        for (var col = 0; col < n; col++)
        {
            var pivot = Enumerable.Range(col, n - col).MaxBy(r => Math.Abs(a[r, col]));
            if (pivot != col)
            {
                for (var c = 0; c < n; c++)
                {
                    (a[col, c], a[pivot, c]) = (a[pivot, c], a[col, c]);
                }

                (b[col], b[pivot]) = (b[pivot], b[col]);
            }

            for (var r = col + 1; r < n; r++)
            {
                var f = a[r, col] / a[col, col];
                for (var c = col; c < n; c++)
                {
                    a[r, c] -= f * a[col, c];
                }

                b[r] -= f * b[col];
            }
        }

        var x = new double[n];
        for (var r = n - 1; r >= 0; r--)
        {
            var sum = b[r];
            for (var c = r + 1; c < n; c++)
            {
                sum -= a[r, c] * x[c];
            }

            x[r] = sum / a[r, r];
        }

        return x;
    }
}
