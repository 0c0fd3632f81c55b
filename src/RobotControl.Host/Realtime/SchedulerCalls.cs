using System.Runtime.InteropServices;

namespace RobotControl.Host.Realtime;

/// <summary>The Linux scheduler calls of <see cref="RealtimeThreads"/> (pid 0: the calling thread).</summary>
internal static partial class SchedulerCalls
{
    public const int SchedOther = 0;
    public const int SchedFifo = 1;
    public const int EPerm = 1;

    /// <summary>Bytes of the CPU masks passed (1024 CPUs, as glibc's cpu_set_t).</summary>
    public const int MaskBytes = 128;

    [LibraryImport("libc", EntryPoint = "sched_getscheduler", SetLastError = true)]
    public static partial int GetScheduler(int pid);

    [LibraryImport("libc", EntryPoint = "sched_setscheduler", SetLastError = true)]
    public static partial int SetScheduler(int pid, int policy, ref int priority);

    [LibraryImport("libc", EntryPoint = "sched_getparam", SetLastError = true)]
    public static partial int GetParam(int pid, ref int priority);

    [LibraryImport("libc", EntryPoint = "sched_get_priority_max", SetLastError = true)]
    public static partial int PriorityMax(int policy);

    [LibraryImport("libc", EntryPoint = "sched_getaffinity", SetLastError = true)]
    public static partial int GetAffinity(int pid, nint size, [Out] byte[] mask);

    [LibraryImport("libc", EntryPoint = "sched_setaffinity", SetLastError = true)]
    public static partial int SetAffinity(int pid, nint size, byte[] mask);
}
