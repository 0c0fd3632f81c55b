using System.Diagnostics;
using System.Globalization;

namespace RobotControl.Host.Realtime;

/// <summary>p50 / p99 / p99.9 / max of a latency distribution, microseconds.</summary>
/// <param name="P50">Median.</param>
/// <param name="P99">99th percentile.</param>
/// <param name="P999">99.9th percentile.</param>
/// <param name="Max">Largest.</param>
public sealed record LatencyQuantiles(double P50, double P99, double P999, double Max);

/// <summary>
/// What the machine itself allows: the wake-up latency of a bare SCHED_FIFO thread sleeping 1 ms at a time, measured
/// by <c>cyclictest</c> (Debian's rt-tests, run as a separate process) at the loop's priority, and the CPU time the
/// hypervisor took from this virtual machine meanwhile (steal, <c>/proc/stat</c>). No loop on this machine can start
/// its ticks more punctually than the first; the second shows when the whole machine was not running. Used by
/// <c>robotctl doctor --latency</c> and before each <c>bench realtime</c> scenario.
/// </summary>
/// <param name="Problem">Why there is no latency measurement (cyclictest missing or failed), else null.</param>
/// <param name="Seconds">How long cyclictest ran.</param>
/// <param name="WakeUpLatencyUs">Its wake-up latency quantiles (from its histogram, 1 us buckets).</param>
/// <param name="Overflows">Wake-ups later than the histogram's range (<see cref="HistogramUs"/>).</param>
/// <param name="StealMs">CPU time stolen by the hypervisor while cyclictest ran, over all CPUs.</param>
public sealed record PlatformFloor(string? Problem, double Seconds, LatencyQuantiles? WakeUpLatencyUs, long Overflows, double StealMs)
{
    /// <summary>The histogram's range: wake-ups later than this count as overflows.</summary>
    public const int HistogramUs = 100_000;

    /// <summary>Runs cyclictest for <paramref name="duration"/> at SCHED_FIFO <paramref name="priority"/> (1 when 0).</summary>
    public static PlatformFloor Measure(TimeSpan duration, int priority)
    {
        var seconds = Math.Max(1, (int)Math.Round(duration.TotalSeconds));
        var c = CultureInfo.InvariantCulture;
        var start = new ProcessStartInfo("cyclictest") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        foreach (var a in new[] { "-q", "-m", "-t1", "-i1000", $"-p{Math.Max(1, priority).ToString(c)}", $"-D{seconds.ToString(c)}s", $"-h{HistogramUs.ToString(c)}" })
        {
            start.ArgumentList.Add(a);
        }

        var stealBefore = StealTicks();
        string output;
        try
        {
            using var process = Process.Start(start)!;
            var error = process.StandardError.ReadToEndAsync();
            output = process.StandardOutput.ReadToEnd();
            process.WaitForExit();
            if (process.ExitCode != 0)
            {
                return new PlatformFloor($"cyclictest exited with {process.ExitCode}: {error.Result.Trim()}", seconds, null, 0, 0);
            }
        }
        catch (System.ComponentModel.Win32Exception ex)
        {
            var why = ex.NativeErrorCode == 2 ? "cyclictest is not installed (apt-get install rt-tests)" : $"cyclictest did not start (error {ex.NativeErrorCode})";
            return new PlatformFloor(why, seconds, null, 0, 0);
        }

        var steal = (StealTicks() - stealBefore) * CpuTimes.MillisecondsPerTick;
        var (latency, overflows) = Parse(output);
        return latency is null
            ? new PlatformFloor("cyclictest printed no histogram", seconds, null, 0, steal)
            : new PlatformFloor(null, seconds, latency, overflows, steal);
    }

    /// <summary>Steal ticks of all CPUs so far (0 where <c>/proc/stat</c> has none).</summary>
    public static long StealTicks() => CpuTimes.Read()?.Steal ?? 0;

    /// <summary>Quantiles and overflows from cyclictest's histogram (<c>-h</c>): lines "latency_us count", "# Histogram Overflows: n".</summary>
    public static (LatencyQuantiles? Latency, long Overflows) Parse(string output)
    {
        var buckets = new List<(int Us, long Count)>();
        long overflows = 0;
        double? max = null;
        foreach (var raw in output.Split('\n'))
        {
            var line = raw.Trim();
            if (line.StartsWith("# Histogram Overflows:", StringComparison.Ordinal))
            {
                overflows = long.Parse(line["# Histogram Overflows:".Length..].Trim(), CultureInfo.InvariantCulture);
            }
            else if (line.StartsWith("# Max Latencies:", StringComparison.Ordinal))
            {
                max = double.Parse(line["# Max Latencies:".Length..].Trim(), CultureInfo.InvariantCulture);
            }
            else if (line.Length > 0 && line[0] != '#')
            {
                var parts = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
                if (parts.Length == 2 && int.TryParse(parts[0], CultureInfo.InvariantCulture, out var us) && long.TryParse(parts[1], CultureInfo.InvariantCulture, out var n) && n > 0)
                {
                    buckets.Add((us, n));
                }
            }
        }

        var total = buckets.Sum(b => b.Count) + overflows;
        if (total == 0)
        {
            return (null, 0);
        }

        double Quantile(double q)
        {
            var rank = (long)Math.Ceiling(q * total);
            long seen = 0;
            foreach (var (us, n) in buckets)
            {
                seen += n;
                if (seen >= rank)
                {
                    return us;
                }
            }

            return HistogramUs; // in the overflow
        }

        return (new LatencyQuantiles(Quantile(0.5), Quantile(0.99), Quantile(0.999), max ?? buckets[^1].Us), overflows);
    }
}
