using System.Diagnostics;
using System.Runtime;
using System.Runtime.CompilerServices;
using RobotControl.Plugins.Sdk;
using RobotControl.Runtime.Graph;

namespace RobotControl.Runtime.Loop;

/// <summary>
/// Runs a <see cref="GraphProgram"/> at a fixed rate on the clock of an injectable <see cref="TimeProvider"/>.
/// Either on its own thread (<see cref="Start(Action)"/>: sleeps, then spins to the deadline; a tick that ends after its
/// deadline counts as a miss and a loop that falls a whole period behind skips ticks rather than bursting), or
/// stepped by the caller (<see cref="Step"/>: one tick at the clock's current time, for virtual clocks; the caller
/// advances the clock one period between steps, which runs exactly like the thread, deterministically). Ticks
/// allocate nothing.
/// </summary>
public sealed class ControlLoop : IDisposable
{
    private readonly TimeProvider _time;
    private readonly long _periodTimestamp;
    private readonly ITickObserver? _observer;
    private Thread? _thread;
    private volatile bool _stopRequested;
    private long _index;
    private long _startTimestamp;
    private long _nextDue;
    private bool _started;
    private Exception? _threadFailure;

    /// <summary>Creates a loop for <paramref name="program"/> at <paramref name="rateHz"/> on <paramref name="time"/>.</summary>
    public ControlLoop(GraphProgram program, TimeProvider time, double rateHz = 1000.0, ITickObserver? observer = null)
    {
        ArgumentNullException.ThrowIfNull(program);
        ArgumentNullException.ThrowIfNull(time);
        if (!LoopRate.IsValid(rateHz))
        {
            throw new ArgumentOutOfRangeException(nameof(rateHz), rateHz, $"the loop rate must lie within {LoopRate.RangeText} Hz");
        }

        Program = program;
        _time = time;
        _observer = observer;
        RateHz = rateHz;
        Period = TimeSpan.FromTicks((long)Math.Round(TimeSpan.TicksPerSecond / rateHz));
        _periodTimestamp = (long)Math.Round(time.TimestampFrequency / rateHz);
    }

    /// <summary>The graph being run.</summary>
    public GraphProgram Program { get; }

    /// <summary>Ticks per second.</summary>
    public double RateHz { get; }

    /// <summary>The nominal period.</summary>
    public TimeSpan Period { get; }

    /// <summary>Tick times and deadline misses.</summary>
    public TickStatistics Statistics { get; } = new();

    /// <summary>
    /// The clock a tick's cost is measured on for <see cref="LastTickCostNs"/>, in nanoseconds (a stepped caller gives
    /// the thread's CPU time); null: not measured.
    /// </summary>
    public Func<long>? CostClock { get; set; }

    /// <summary>What the last tick cost on <see cref="CostClock"/>, nanoseconds, without the time spent compiling (0: not measured).</summary>
    public long LastTickCostNs { get; private set; }

    /// <summary>Ticks run so far.</summary>
    public long TickCount => Volatile.Read(ref _index);

    /// <summary>
    /// The loop-clock timestamp at which the next tick is due. A stepped caller advances its clock to this (normally
    /// one period after the last tick; later after an overrun, whose missed slots are skipped).
    /// </summary>
    public long NextDueTimestamp => _nextDue;

    /// <summary>The exception that ended the loop thread (the graph isolates plug-in faults; this is anything else).</summary>
    public Exception? ThreadFailure => _threadFailure;

    /// <summary>
    /// Methods the JIT compiled on the loop thread after its first tick (0 when every path ran before, or had been
    /// compiled ahead); known once the thread has ended (<see cref="Stop()"/>).
    /// </summary>
    public long MethodsCompiledAfterFirstTick { get; private set; }

    /// <summary>Time the loop thread spent in the JIT after its first tick (see <see cref="MethodsCompiledAfterFirstTick"/>).</summary>
    public TimeSpan CompileTimeAfterFirstTick { get; private set; }

    /// <summary>Runs one tick at the clock's current time (virtual-time use). Starts the graph on the first call.</summary>
    public void Step()
    {
        if (_thread is not null)
        {
            throw new InvalidOperationException("the loop runs on its own thread; Step is for stepped (virtual-time) use");
        }

        EnsureStarted();
        RunTick(_time.GetTimestamp());
    }

    /// <summary>
    /// A stepped caller's measure of the tick it just ran (virtual-time use): it finished at
    /// <paramref name="finishedTimestamp"/> on the loop clock, later than the clock showed (its measured cost). Its
    /// deadline and the slots it overran count as on the loop's own thread, and <see cref="NextDueTimestamp"/> moves
    /// past the skipped slots.
    /// </summary>
    public void Overran(long finishedTimestamp)
    {
        if (_thread is not null)
        {
            throw new InvalidOperationException("the loop runs on its own thread: it times its ticks itself");
        }

        CountDeadline(_nextDue, finishedTimestamp); // the last tick moved its next due time one period past its own: its deadline
    }

    /// <summary>Starts the loop thread.</summary>
    public void Start() => Start(static () => { });

    /// <summary>
    /// Starts the loop thread, which first runs <paramref name="prologue"/> (e.g. to give itself real-time scheduling,
    /// which .NET threads do not inherit).
    /// </summary>
    public void Start(Action prologue)
    {
        ArgumentNullException.ThrowIfNull(prologue);
        if (_thread is not null || _started)
        {
            throw new InvalidOperationException("the loop was already started");
        }

        _thread = new Thread(() =>
        {
            prologue();
            ThreadMain();
        }) { Name = "control loop", IsBackground = true, Priority = ThreadPriority.Highest };
        _thread.Start();
    }

    /// <summary>Stops the loop thread (if any) and the graph.</summary>
    public void Stop() => _ = Stop(Timeout.InfiniteTimeSpan);

    /// <summary>
    /// Stops the loop thread (if any), waiting at most <paramref name="timeout"/> for its tick to end, then the graph.
    /// False when the thread is still in a tick (a plug-in's <c>Tick</c> that does not return: <see
    /// cref="GraphProgram.Profile"/> names it): the graph's plug-ins are then not stopped, since their tick still runs;
    /// the thread is a background thread and ends with the process.
    /// </summary>
    public bool Stop(TimeSpan timeout)
    {
        _stopRequested = true;
        if (_thread is { } thread && thread != Thread.CurrentThread && !thread.Join(timeout))
        {
            return false;
        }

        Program.Stop();
        return true;
    }

    /// <inheritdoc />
    public void Dispose() => Stop();

    private void EnsureStarted()
    {
        if (_started)
        {
            return;
        }

        _started = true;
        _startTimestamp = _time.GetTimestamp();
        _nextDue = _startTimestamp;
        Program.Start(new TickContext(0, _startTimestamp, TimeSpan.Zero, Period));
    }

    // Optimized once, before the first tick: a loop that runs for the whole session would otherwise start as quick
    // (tier-0) code and be replaced on the stack once it had looped long enough, a synchronous compile on this thread
    // (14 ms, 11 s into a run; docs/perf/realtime.md).
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void ThreadMain()
    {
        var afterFirstTick = false;
        var compiledMethods = 0L;
        var compileTime = TimeSpan.Zero;
        try
        {
            EnsureStarted();
            while (!_stopRequested)
            {
                WaitUntil(_nextDue);
                if (_stopRequested)
                {
                    break;
                }

                var now = _time.GetTimestamp();
                Statistics.RecordStartLag((now - _nextDue) * 1e6 / _time.TimestampFrequency);
                RunTick(now);
                if (!afterFirstTick)
                {
                    afterFirstTick = true;
                    compiledMethods = JitInfo.GetCompiledMethodCount(currentThread: true); // after the first tick
                    compileTime = JitInfo.GetCompilationTime(currentThread: true);
                }
            }
        }
#pragma warning disable CA1031 // surfaced through ThreadFailure; the harness reports it
        catch (Exception ex)
#pragma warning restore CA1031
        {
            _threadFailure = ex;
        }
        finally
        {
            if (afterFirstTick)
            {
                MethodsCompiledAfterFirstTick = JitInfo.GetCompiledMethodCount(currentThread: true) - compiledMethods;
                CompileTimeAfterFirstTick = JitInfo.GetCompilationTime(currentThread: true) - compileTime;
            }
        }
    }

    private void WaitUntil(long due)
    {
        var frequency = _time.TimestampFrequency;
        if (ReferenceEquals(_time, TimeProvider.System) && MonotonicSleep.Available)
        {
            // The system clock is the monotonic one: sleep to just before the deadline, then spin the last few
            // microseconds. Sleeping (not spinning) keeps a SCHED_FIFO loop inside the kernel's real-time budget.
            var spin = frequency / 50_000; // 20 us
            while (!_stopRequested && due - _time.GetTimestamp() > spin)
            {
                MonotonicSleep.Until(due - spin);
            }
        }

        while (!_stopRequested)
        {
            var remaining = due - _time.GetTimestamp();
            if (remaining <= 0)
            {
                return;
            }

            // Sleep while more than ~1.5 ms remain (the OS sleeps at least 1 ms), then spin politely to the deadline.
            if (remaining * 1000 > frequency * 3 / 2)
            {
                Thread.Sleep(1);
            }
            else
            {
                Thread.SpinWait(50);
            }
        }
    }

    private void RunTick(long now)
    {
        var index = _index;
        var elapsed = _time.GetElapsedTime(_startTimestamp, now);
        var context = new TickContext(index, now, elapsed, Period);
        var costClock = CostClock;
        var costBegin = costClock?.Invoke() ?? 0;
        var jitBegin = costClock is null ? TimeSpan.Zero : JitInfo.GetCompilationTime(currentThread: true);
        var begin = Stopwatch.GetTimestamp();
        Program.Tick(context);
        var end = Stopwatch.GetTimestamp();
        if (costClock is not null)
        {
            LastTickCostNs = costClock() - costBegin - (long)((JitInfo.GetCompilationTime(currentThread: true) - jitBegin).TotalMicroseconds * 1e3);
        }

        Statistics.Record(end - begin);

        // Deadline: the tick due at _nextDue must finish (on the loop clock) before the next one is due.
        CountDeadline(_nextDue + _periodTimestamp, _time.GetTimestamp());
        Volatile.Write(ref _index, index + 1);
        _observer?.AfterTick(context);
    }

    /// <summary>
    /// A tick whose deadline was <paramref name="deadline"/> finished at <paramref name="finished"/> (loop clock): a miss
    /// when late, and a whole period (or more) behind, the ticks that cannot be run in time are skipped (misses too)
    /// instead of bursting. The next tick is due at the deadline or, after skipping, later.
    /// </summary>
    private void CountDeadline(long deadline, long finished)
    {
        long misses = finished > deadline ? 1 : 0;
        _nextDue = deadline;
        if (finished > deadline + _periodTimestamp)
        {
            var behind = (finished - deadline) / _periodTimestamp;
            _nextDue += behind * _periodTimestamp;
            misses += behind;
        }

        if (misses > 0)
        {
            Statistics.AddDeadlineMisses(misses);
        }
    }
}
