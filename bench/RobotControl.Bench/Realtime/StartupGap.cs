using System.Diagnostics;
using System.Globalization;

namespace RobotControl.Bench.Realtime;

/// <summary>
/// One long bus cycle of the traced start of a run, taken apart from its link calls: how long the host spent waiting
/// for bytes (reads), how many reads came back empty, and the longest stretch in which the host made no link call at
/// all (the bus thread not running: preempted, stalled or suspended).
/// </summary>
/// <param name="AtS">When the cycle started, seconds after the first traced cycle (the warm-up's; the motors go on about 0.3 s later).</param>
/// <param name="CycleMs">The cycle's length, start to next start.</param>
/// <param name="ReadWaitMs">Time spent inside reads.</param>
/// <param name="EmptyReads">Reads that returned no byte (waited their whole timeout).</param>
/// <param name="LongestIdleMs">The longest time between the end of one link call and the start of the next.</param>
/// <param name="Calls">The cycle's link calls: offset (ms), kind, instruction/ID of writes, bytes, duration.</param>
internal sealed record StartupGap(double AtS, double CycleMs, double ReadWaitMs, int EmptyReads, double LongestIdleMs, IReadOnlyList<string> Calls)
{
    /// <summary>The <paramref name="count"/> longest cycles among those fully inside the trace, longest first.</summary>
    public static IReadOnlyList<StartupGap> Longest(ReadOnlySpan<long> starts, ReadOnlySpan<LinkCall> trace, int count)
    {
        if (trace.Length == 0 || starts.Length < 2)
        {
            return [];
        }

        var traceEnd = trace[^1].End;
        var cycles = new List<(int Index, long Length)>();
        for (var i = 0; i + 1 < starts.Length && starts[i + 1] <= traceEnd; i++)
        {
            cycles.Add((i, starts[i + 1] - starts[i]));
        }

        var gaps = new List<StartupGap>();
        foreach (var (index, _) in cycles.OrderByDescending(c => c.Length).Take(count))
        {
            gaps.Add(Of(starts[0], starts[index], starts[index + 1], trace));
        }

        return gaps;
    }

    private static StartupGap Of(long origin, long from, long to, ReadOnlySpan<LinkCall> trace)
    {
        static double Ms(long ticks) => ticks * 1000.0 / Stopwatch.Frequency;
        var calls = new List<string>();
        long readWait = 0, longestIdle = 0, lastEnd = from;
        var empty = 0;
        foreach (var c in trace)
        {
            if (c.Start < from || c.Start >= to)
            {
                continue;
            }

            longestIdle = Math.Max(longestIdle, c.Start - lastEnd);
            lastEnd = c.End;
            if (c.Kind == 'R')
            {
                readWait += c.End - c.Start;
                empty += c.Bytes == 0 ? 1 : 0;
            }

            var what = c.Kind == 'W' ? $"W 0x{c.Instruction:X2} id {c.Id}" : c.Kind == 'R' ? $"R (timeout {c.TimeoutUs} us)" : "D";
            calls.Add(string.Create(CultureInfo.InvariantCulture, $"+{Ms(c.Start - from):F3} ms {what} {c.Bytes} B, {Ms(c.End - c.Start):F3} ms"));
        }

        longestIdle = Math.Max(longestIdle, to - lastEnd);
        return new StartupGap(Ms(from - origin) / 1000, Ms(to - from), Ms(readWait), empty, Ms(longestIdle), calls);
    }
}
