using RobotControl.Runtime.Loop;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// What the live session's own thread reports of itself: where it is (starting, running, stopped, failed), how long
/// the virtual robot's bus cycles took and what the loop's ticks allocated on it.
/// <para>Written by the session thread only; read by the status thread, the timings and an emergency stop's answer.</para>
/// </summary>
internal sealed class SessionThreadState
{
    private volatile string _phase = "starting";
    private long _tickAllocatedBytes;

    /// <summary>starting, running, stopped or failed (the status's <c>session</c>).</summary>
    public string Phase
    {
        get => _phase;
        set => _phase = value;
    }

    /// <summary>The virtual robot's bus cycles (write, read, publish, check, between cycles), timed on the session thread.</summary>
    public TickStatistics BusCycle { get; } = new();

    /// <summary>Bytes the loop's ticks allocated on the session thread (virtual sessions).</summary>
    public long TickAllocatedBytes => Interlocked.Read(ref _tickAllocatedBytes);

    /// <summary>Counts what one tick allocated.</summary>
    public void AddTickAllocation(long bytes) => Interlocked.Add(ref _tickAllocatedBytes, bytes);
}
