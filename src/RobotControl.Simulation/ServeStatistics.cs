using System.Diagnostics;
using System.Runtime;
using System.Runtime.CompilerServices;

namespace RobotControl.Simulation;

/// <summary>How <see cref="VirtualRobot.Serve"/> kept up with the wall clock: the time it slipped, its longest stall, the JIT's work while serving.</summary>
public sealed class ServeStatistics
{
    private long _start;
    private long _last;
    private TimeSpan _lastCpu;
    private long _compiledAtFirstTurn = -1;
    private TimeSpan _compileTimeAtFirstTurn;

    /// <summary>Wall-clock time the real-time simulation fell behind and skipped.</summary>
    public TimeSpan SlippedTime { get; internal set; }

    /// <summary>
    /// The longest wall-clock time between two turns of the serving loop (a turn waits up to 200 us for bytes, then
    /// simulates up to now): longer than about 1 ms, the simulator was not running (preempted, paused, stalled).
    /// </summary>
    public TimeSpan LongestServeGap { get; private set; }

    /// <summary>When the <see cref="LongestServeGap"/> began, wall-clock time after serving started.</summary>
    public TimeSpan LongestServeGapAt { get; private set; }

    /// <summary>CPU time the process used during the <see cref="LongestServeGap"/>: about the gap, it was busy; about 0, it was not running.</summary>
    public TimeSpan LongestServeGapCpu { get; private set; }

    /// <summary>Methods the JIT compiled on the serving thread after its first turn; known once serving has ended.</summary>
    public long MethodsCompiledWhileServing { get; private set; }

    /// <summary>Time the serving thread spent in the JIT after its first turn (see <see cref="MethodsCompiledWhileServing"/>).</summary>
    public TimeSpan CompileTimeWhileServing { get; private set; }

    internal void Start(long timestamp) => (_start, _last, _lastCpu) = (timestamp, timestamp, Environment.CpuUsage.TotalTime);

    /// <summary>A turn of the loop begins at <paramref name="now"/>: keeps the longest gap since the last.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)] // called every turn of the serving loop, which is compiled so too
    internal void Turn(long now)
    {
        var cpu = Environment.CpuUsage.TotalTime;
        if (now - _last > LongestServeGap.Ticks * Stopwatch.Frequency / TimeSpan.TicksPerSecond)
        {
            LongestServeGap = Stopwatch.GetElapsedTime(_last, now);
            LongestServeGapAt = Stopwatch.GetElapsedTime(_start, _last);
            LongestServeGapCpu = cpu - _lastCpu;
        }

        (_last, _lastCpu) = (now, cpu);
    }

    /// <summary>The first turn is done (on the serving thread): the JIT's work from here on counts.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void FirstTurnDone()
    {
        if (_compiledAtFirstTurn < 0)
        {
            _compiledAtFirstTurn = JitInfo.GetCompiledMethodCount(currentThread: true);
            _compileTimeAtFirstTurn = JitInfo.GetCompilationTime(currentThread: true);
        }
    }

    /// <summary>Serving ended (on the serving thread).</summary>
    internal void Stop()
    {
        if (_compiledAtFirstTurn >= 0)
        {
            MethodsCompiledWhileServing = JitInfo.GetCompiledMethodCount(currentThread: true) - _compiledAtFirstTurn;
            CompileTimeWhileServing = JitInfo.GetCompilationTime(currentThread: true) - _compileTimeAtFirstTurn;
        }
    }
}
