using System.Runtime.InteropServices;

namespace RobotControl.Bench.Ik;

/// <summary>
/// CPU time of the calling thread (Linux CLOCK_THREAD_CPUTIME_ID): unlike wall time it does not count the time the
/// thread sat descheduled, which dominates means on a shared, oversubscribed machine. NaN where unavailable.
/// </summary>
internal static class ThreadCpuClock
{
    private const int ClockThreadCpuTimeId = 3;

    public static double NowUs()
    {
        if (!OperatingSystem.IsLinux())
        {
            return double.NaN;
        }

        return NativeMethods.clock_gettime(ClockThreadCpuTimeId, out var ts) == 0 ? (ts.Seconds * 1e6) + (ts.Nanoseconds * 1e-3) : double.NaN;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    private static class NativeMethods
    {
        [DllImport("libc", SetLastError = false)]
        [DefaultDllImportSearchPaths(DllImportSearchPath.SafeDirectories)]
#pragma warning disable SYSLIB1054 // LibraryImport needs AllowUnsafeBlocks, which the bench project does not set.
        public static extern int clock_gettime(int clockId, out TimeSpec time);
#pragma warning restore SYSLIB1054
    }
}
