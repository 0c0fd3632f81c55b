using System.Runtime.InteropServices;

namespace RobotControl.Host.Session;

/// <summary>
/// The calling thread's CPU time (Linux <c>CLOCK_THREAD_CPUTIME_ID</c>): what a tick cost the machine, without the
/// time the thread waited for a CPU. The virtual schedule counts a tick's cost on it, so that a busy machine running
/// the tests does not look like a slow plug-in; the benchmarks print it beside wall time. Elsewhere
/// (<see cref="Available"/> false) it reads 0 (NaN in microseconds).
/// </summary>
internal static partial class ThreadCpuClock
{
    private const int ThreadCpuTimeId = 3;

    /// <summary>True where the clock can be read.</summary>
    public static bool Available { get; } = OperatingSystem.IsLinux() && Read(out _);

    /// <summary>The calling thread's CPU time so far, nanoseconds (0 where not <see cref="Available"/>).</summary>
    public static long NowNs() => Available && Read(out var ns) ? ns : 0;

    /// <summary>The calling thread's CPU time so far, microseconds (NaN where not <see cref="Available"/>: the benchmarks print it beside wall time).</summary>
    public static double NowUs() => Available && Read(out var ns) ? ns * 1e-3 : double.NaN;

    private static bool Read(out long ns)
    {
        if (ClockGetTime(ThreadCpuTimeId, out var ts) != 0)
        {
            ns = 0;
            return false;
        }

        ns = (ts.Seconds * 1_000_000_000) + ts.Nanoseconds;
        return true;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    [LibraryImport("libc", EntryPoint = "clock_gettime")]
    private static partial int ClockGetTime(int clock, out TimeSpec time);
}
