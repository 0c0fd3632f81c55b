using System.Globalization;

namespace RobotControl.Host.Realtime;

/// <summary>The machine's CPU time so far, all CPUs, from the first line of <c>/proc/stat</c> (in USER_HZ ticks).</summary>
/// <param name="Total">Every kind of time (user, nice, system, idle, iowait, irq, softirq, steal).</param>
/// <param name="Steal">Time the hypervisor ran something else while this virtual machine had work.</param>
public sealed record CpuTimes(long Total, long Steal)
{
    /// <summary>Milliseconds per tick: USER_HZ is 100 on every Linux architecture .NET runs on.</summary>
    public const double MillisecondsPerTick = 10;

    /// <summary>Reads <paramref name="procStat"/>; null when it is missing or has no cpu line.</summary>
    public static CpuTimes? Read(string procStat = "/proc/stat")
    {
        try
        {
            var line = File.ReadLines(procStat).FirstOrDefault();
            return line is null ? null : Parse(line);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    /// <summary>The times of a <c>cpu  user nice system idle iowait irq softirq steal ...</c> line; null when it is not one.</summary>
    public static CpuTimes? Parse(string line)
    {
        ArgumentNullException.ThrowIfNull(line);
        var fields = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
        if (fields.Length < 5 || fields[0] != "cpu")
        {
            return null;
        }

        long total = 0, steal = 0;
        for (var i = 1; i < Math.Min(fields.Length, 9); i++) // guest times (9, 10) are already in user and nice
        {
            if (!long.TryParse(fields[i], NumberStyles.None, CultureInfo.InvariantCulture, out var v))
            {
                return null;
            }

            total += v;
            steal = i == 8 ? v : steal;
        }

        return new CpuTimes(total, steal);
    }
}
