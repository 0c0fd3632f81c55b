using System.Globalization;
using System.Runtime.InteropServices;

namespace RobotControl.Host.Realtime;

/// <summary>
/// How the real-time threads (bus, control loop) are scheduled: SCHED_FIFO at <see cref="Priority"/> for both (0: the
/// normal scheduler), pinned to <see cref="Cpu"/> (null: any CPU). One priority for both: the threads share values
/// through spinning seqlocks, and a reader that spins at a higher priority than a writer it preempted on the same CPU
/// keeps it from finishing (measured: 27 % deadline misses with the bus thread one priority below the loop, 0.63 % at
/// one priority, docs/perf/realtime.md); at one priority the spinner's yield lets the writer run.
/// .NET threads do not inherit the creating thread's policy (a new managed thread starts under SCHED_OTHER, measured by
/// <c>RealtimeThreadsTests</c>), so each thread applies its scheduling to itself first thing (<see cref="Start"/>
/// hands each one its prologue). Where the process may not have real-time priority (no CAP_SYS_NICE, RLIMIT_RTPRIO 0)
/// this is said in <see cref="Outcome"/> and the threads run normally.
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

    /// <summary>Hold the CPUs' wake-up latency at 0 us while the threads run (<see cref="CpuLatencyHold"/>); true unless a benchmark compares.</summary>
    public bool HoldCpuLatency { get; init; } = true;

    /// <summary>What the threads got, in one line (complete once <see cref="Start"/> returns).</summary>
    public string Outcome { get; private set; } = "not started";

    /// <summary>True when the threads got SCHED_FIFO.</summary>
    public bool GotRealtimePriority { get; private set; }

    /// <summary>How long <see cref="Start"/> waits for the threads to apply their scheduling.</summary>
    private static readonly TimeSpan PrologueTimeout = TimeSpan.FromSeconds(5);

    /// <summary>
    /// Starts the bus thread and the control loop's thread, each given the prologue it must run first on its own
    /// thread (both at <see cref="Priority"/>, on <see cref="Cpu"/>). Returns once both prologues have run.
    /// </summary>
    /// <exception cref="TimeoutException">A thread did not run its prologue within 5 s.</exception>
    public void Start(Action<Action> startBus, Action<Action> startLoop)
    {
        ArgumentNullException.ThrowIfNull(startBus);
        Begin(startBus, startLoop);
    }

    /// <summary>
    /// Starts the control loop's thread alone (a station without a robot has no bus thread), given the prologue it must
    /// run first on its own thread. Returns once it has run.
    /// </summary>
    /// <exception cref="TimeoutException">The thread did not run its prologue within 5 s.</exception>
    public void StartLoop(Action<Action> startLoop) => Begin(null, startLoop);

    private void Begin(Action<Action>? startBus, Action<Action> startLoop)
    {
        ArgumentNullException.ThrowIfNull(startLoop);
        if (!OperatingSystem.IsLinux() || (Priority == 0 && Cpu is null))
        {
            Outcome = "normal scheduling, any CPU";
            startBus?.Invoke(static () => { });
            startLoop(static () => { });
            return;
        }

        string? bus = null, loop = null;
        using var applied = new CountdownEvent(startBus is null ? 1 : 2);
        startBus?.Invoke(() =>
        {
            bus = ApplyToCurrentThread(Priority);
            applied.Signal();
        });
        startLoop(() =>
        {
            loop = ApplyToCurrentThread(Priority);
            applied.Signal();
        });
        if (!applied.Wait(PrologueTimeout))
        {
            throw new TimeoutException(startBus is null ? "the loop thread did not apply its scheduling within 5 s" : "the bus and loop threads did not apply their scheduling within 5 s");
        }

        Outcome = startBus is null || loop == bus ? loop! : $"loop thread: {loop}; bus thread: {bus}";
    }

    /// <summary>
    /// Raises the calling thread to SCHED_FIFO at this priority (on this CPU) and sets it back afterwards: whether the
    /// process may have real-time priority at all (<see cref="Outcome"/>, <see cref="GotRealtimePriority"/>).
    /// </summary>
    public void Probe()
    {
        if (!OperatingSystem.IsLinux())
        {
            Outcome = "normal scheduling, any CPU";
            return;
        }

        var policy = SchedulerCalls.GetScheduler(0);
        var priority = 0;
        _ = SchedulerCalls.GetParam(0, ref priority);
        var mask = new byte[SchedulerCalls.MaskBytes];
        var haveMask = SchedulerCalls.GetAffinity(0, mask.Length, mask) == 0;
        try
        {
            Outcome = ApplyToCurrentThread(Priority);
        }
        finally
        {
            _ = SchedulerCalls.SetScheduler(0, policy, ref priority);
            if (haveMask)
            {
                _ = SchedulerCalls.SetAffinity(0, mask.Length, mask);
            }
        }
    }

    /// <summary>SCHED_FIFO at <paramref name="priority"/> and the CPU pin for the calling thread; says what it got.</summary>
    private string ApplyToCurrentThread(int priority) => $"{RaisePriority(priority)}; {Pin()}";

    private string RaisePriority(int priority)
    {
        if (priority == 0)
        {
            return "normal scheduling";
        }

        var p = Math.Min(priority, SchedulerCalls.PriorityMax(SchedulerCalls.SchedFifo));
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
