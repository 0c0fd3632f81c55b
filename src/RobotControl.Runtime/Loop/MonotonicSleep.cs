using System.Diagnostics;
using System.Runtime.InteropServices;

namespace RobotControl.Runtime.Loop;

/// <summary>
/// Sleeps until an absolute <see cref="Stopwatch"/> timestamp with <c>clock_nanosleep(CLOCK_MONOTONIC,
/// TIMER_ABSTIME)</c>, the clock <see cref="Stopwatch"/> reads on Linux (nanoseconds). Wake-up is within tens of
/// microseconds (timer slack; none for SCHED_FIFO threads), so the loop need not spin, and a real-time thread that
/// does not spin is not throttled by the kernel's real-time CPU budget.
/// </summary>
internal static partial class MonotonicSleep
{
    private const int ClockMonotonic = 1;
    private const int TimerAbsoluteTime = 1;

    /// <summary>True where <see cref="Until"/> works: Linux, with <see cref="Stopwatch"/> counting nanoseconds.</summary>
    public static bool Available { get; } = OperatingSystem.IsLinux() && Stopwatch.Frequency == 1_000_000_000;

    /// <summary>Sleeps until <paramref name="stopwatchTimestamp"/> (returns early on a signal; callers loop).</summary>
    public static void Until(long stopwatchTimestamp)
    {
        var request = new Timespec(stopwatchTimestamp / 1_000_000_000, stopwatchTimestamp % 1_000_000_000);
        _ = ClockNanosleep(ClockMonotonic, TimerAbsoluteTime, in request, 0);
    }

    [LibraryImport("libc", EntryPoint = "clock_nanosleep")]
    private static partial int ClockNanosleep(int clock, int flags, in Timespec request, nint remain);

    [StructLayout(LayoutKind.Sequential)]
    private readonly record struct Timespec(long Seconds, long Nanoseconds);
}
