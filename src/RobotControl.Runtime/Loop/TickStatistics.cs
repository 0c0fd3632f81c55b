using System.Diagnostics;

namespace RobotControl.Runtime.Loop;

/// <summary>
/// Tick execution times (from <see cref="Stopwatch"/> timestamps: real CPU time even on a virtual clock) in a
/// fixed histogram of 0.1 us bins up to 10 ms, plus the exact maximum; and deadline misses counted on the loop's
/// clock. Recording allocates nothing. One writer (the loop); readers may sample while it runs.
/// </summary>
public sealed class TickStatistics
{
    private const double BinUs = 0.1;
    private const int Bins = 100_000;
    private const int LagBins = 100_000; // 1 us bins up to 100 ms
    private readonly int[] _histogram = new int[Bins + 1];
    private readonly int[] _lagHistogram = new int[LagBins + 1];
    private long _count;
    private long _lagCount;
    private long _maxLagUs;
    private long _maxStopwatchTicks;
    private long _deadlineMisses;

    /// <summary>Ticks recorded.</summary>
    public long Count => Volatile.Read(ref _count);

    /// <summary>Ticks that ended after their deadline (or were skipped because the loop fell a whole period behind).</summary>
    public long DeadlineMisses => Volatile.Read(ref _deadlineMisses);

    /// <summary>Longest tick, microseconds.</summary>
    public double MaxUs => ToUs(Volatile.Read(ref _maxStopwatchTicks));

    /// <summary>Median tick time, microseconds (0.1 us resolution).</summary>
    public double MedianUs => Percentile(0.5);

    /// <summary>99th-percentile tick time, microseconds (0.1 us resolution).</summary>
    public double P99Us => Percentile(0.99);

    /// <summary>Records one tick's duration in <see cref="Stopwatch"/> ticks.</summary>
    public void Record(long stopwatchTicks)
    {
        var us = ToUs(stopwatchTicks);
        var bin = (int)Math.Min(Bins, us / BinUs);
        _histogram[bin]++;
        if (stopwatchTicks > _maxStopwatchTicks)
        {
            Volatile.Write(ref _maxStopwatchTicks, stopwatchTicks);
        }

        Volatile.Write(ref _count, _count + 1);
    }

    /// <summary>Ticks whose start lag was recorded (ticks run on the loop's own thread).</summary>
    public long StartLagCount => Volatile.Read(ref _lagCount);

    /// <summary>Largest tick start lag (start after the tick was due, on the loop clock), microseconds.</summary>
    public double StartLagMaxUs => Volatile.Read(ref _maxLagUs);

    /// <summary>Records how late a tick started after it was due (the tick start jitter), microseconds.</summary>
    public void RecordStartLag(double us)
    {
        var whole = (long)Math.Max(0, Math.Round(us));
        _lagHistogram[(int)Math.Min(LagBins, whole)]++;
        if (whole > _maxLagUs)
        {
            Volatile.Write(ref _maxLagUs, whole);
        }

        Volatile.Write(ref _lagCount, _lagCount + 1);
    }

    /// <summary>The <paramref name="fraction"/> quantile (0..1) of the tick start lag in microseconds (1 us bins; the max caps it).</summary>
    public double StartLagPercentile(double fraction)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(fraction, 0.0);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(fraction, 1.0);
        var count = StartLagCount;
        var rank = Math.Max(1, (long)Math.Ceiling(fraction * count));
        long seen = 0;
        for (var bin = 0; bin <= LagBins && count > 0; bin++)
        {
            seen += _lagHistogram[bin];
            if (seen >= rank)
            {
                return Math.Min(StartLagMaxUs, bin);
            }
        }

        return StartLagMaxUs;
    }

    /// <summary>Counts missed deadlines.</summary>
    public void AddDeadlineMisses(long misses) => Volatile.Write(ref _deadlineMisses, _deadlineMisses + misses);

    /// <summary>The <paramref name="fraction"/> quantile (0..1) of the tick time in microseconds (upper bin edge; the max caps it).</summary>
    public double Percentile(double fraction)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(fraction, 0.0);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(fraction, 1.0);
        var count = Count;
        if (count == 0)
        {
            return 0;
        }

        var rank = (long)Math.Ceiling(fraction * count);
        long seen = 0;
        for (var bin = 0; bin <= Bins; bin++)
        {
            seen += _histogram[bin];
            if (seen >= Math.Max(1, rank))
            {
                return Math.Min(MaxUs, (bin + 1) * BinUs);
            }
        }

        return MaxUs;
    }

    private static double ToUs(long stopwatchTicks) => stopwatchTicks * 1e6 / Stopwatch.Frequency;
}
