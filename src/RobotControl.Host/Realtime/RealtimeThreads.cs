using System.Globalization;
using System.Runtime.InteropServices;

namespace RobotControl.Host.Realtime;

/// <summary>
/// How the real-time threads (bus, control loop) are scheduled: SCHED_FIFO at <see cref="Priority"/> (0: the normal
/// scheduler) and pinned to <see cref="Cpu"/> (null: any CPU). Linux threads inherit the scheduling policy, priority
/// and CPU mask of the thread that creates them, so <see cref="Start"/> gives them to the calling thread, starts the
/// threads, and gives the calling thread back its own. Where the process may not have real-time priority (no
/// CAP_SYS_NICE, RLIMIT_RTPRIO 0) this is said once in <see cref="Outcome"/> and the threads run normally.
/// </summary>
public sealed class RealtimeThreads
{
    /// <summary>Normal scheduling, any CPU.</summary>
    public static RealtimeThreads Default { get; } = new(0, null);

    /// <summary>Schedules with SCHED_FIFO at <paramref name="priority"/> (1..99; 0: normal) on <paramref name="cpu"/> (null: any).</summary>
    /// <exception cref="ArgumentOutOfRangeException">The priority is outside 0..99, or the CPU is not one of this machine's.</exception>
    public RealtimeThreads(int priority, int? cpu)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(priority);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(priority, 99);
        if (cpu is { } c)
        {
            ArgumentOutOfRangeException.ThrowIfNegative(c, nameof(cpu));
            ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(c, Environment.ProcessorCount, nameof(cpu));
        }

        Priority = priority;
        Cpu = cpu;
    }

    /// <summary>SCHED_FIFO priority (0: the normal scheduler).</summary>
    public int Priority { get; }

    /// <summary>The CPU the threads are pinned to (null: any).</summary>
    public int? Cpu { get; }

    /// <summary>What the threads got, in one line (set by <see cref="Start"/>).</summary>
    public string Outcome { get; private set; } = "not started";

    /// <summary>True when the threads got SCHED_FIFO.</summary>
    public bool GotRealtimePriority { get; private set; }

    /// <summary>Runs <paramref name="startThreads"/> (which creates the threads) with this scheduling, then restores the calling thread's.</summary>
    public void Start(Action startThreads)
    {
        ArgumentNullException.ThrowIfNull(startThreads);
        if (!OperatingSystem.IsLinux() || (Priority == 0 && Cpu is null))
        {
            Outcome = "normal scheduling, any CPU";
            startThreads();
            return;
        }

        var policy = SchedulerCalls.GetScheduler(0);
        var priority = 0;
        _ = SchedulerCalls.GetParam(0, ref priority);
        var mask = new byte[SchedulerCalls.MaskBytes];
        var haveMask = SchedulerCalls.GetAffinity(0, mask.Length, mask) == 0;
        var said = new List<string>();
        try
        {
            said.Add(RaisePriority());
            said.Add(Pin());
            startThreads();
        }
        finally
        {
            _ = SchedulerCalls.SetScheduler(0, policy, ref priority);
            if (haveMask)
            {
                _ = SchedulerCalls.SetAffinity(0, mask.Length, mask);
            }

            Outcome = string.Join("; ", said);
        }
    }

    private string RaisePriority()
    {
        if (Priority == 0)
        {
            return "normal scheduling";
        }

        var p = Math.Min(Priority, SchedulerCalls.PriorityMax(SchedulerCalls.SchedFifo));
        if (SchedulerCalls.SetScheduler(0, SchedulerCalls.SchedFifo, ref p) == 0)
        {
            GotRealtimePriority = true;
            return string.Create(CultureInfo.InvariantCulture, $"SCHED_FIFO priority {p}");
        }

        var errno = Marshal.GetLastPInvokeError();
        return errno == SchedulerCalls.EPerm
            ? "no real-time priority: the process may not use SCHED_FIFO (needs CAP_SYS_NICE or an rtprio limit in /etc/security/limits.conf); running with normal scheduling"
            : $"no real-time priority: sched_setscheduler failed ({Marshal.GetPInvokeErrorMessage(errno)}); running with normal scheduling";
    }

    private string Pin()
    {
        if (Cpu is not { } cpu)
        {
            return "any CPU";
        }

        var mask = new byte[SchedulerCalls.MaskBytes];
        mask[cpu / 8] = (byte)(1 << (cpu % 8));
        return SchedulerCalls.SetAffinity(0, mask.Length, mask) == 0
            ? string.Create(CultureInfo.InvariantCulture, $"pinned to CPU {cpu}")
            : $"not pinned to CPU {cpu}: {Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError())}";
    }
}
