using System.Runtime;
using System.Runtime.CompilerServices;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The bus thread of a wall-clock session: it owns the bus and runs the robot's one cycle back to back (no faster than
/// <see cref="BusRobotOptions.MinimumCyclePeriod"/>) until stopped. A cycle the link fails (an <see cref="IOException"/>)
/// is an event and a degraded bus, and the thread goes on after a short pause; the safety supervisor sees the gap.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class BusThread(BusRobot robot, BusRobotOptions options, TimeProvider time)
{
    private static readonly TimeSpan PauseAfterFailure = TimeSpan.FromMilliseconds(10);
    private static readonly TimeSpan RepeatedFailureReport = TimeSpan.FromSeconds(1);
    private Thread? _thread;
    private volatile bool _stopping;
    private string? _lastFailure;
    private long _lastFailureReported;
    private int _failuresLeftOut;

    public bool IsRunning => _thread is not null;

    /// <summary>Methods the JIT compiled on the bus thread after its first cycle (paths first taken later); known once the thread has ended.</summary>
    public long MethodsCompiledAfterFirstCycle { get; private set; }

    public TimeSpan CompileTimeAfterFirstCycle { get; private set; }

    public void Start(Action prologue)
    {
        ArgumentNullException.ThrowIfNull(prologue);
        if (_thread is not null)
        {
            return;
        }

        _stopping = false;
        var started = new ManualResetEventSlim();
        _thread = new Thread(() =>
        {
            prologue();
            using var own = robot.OwnBus();
            started.Set();
            Loop();
        }) { IsBackground = true, Name = $"bus {robot.Definition.Name}", Priority = ThreadPriority.AboveNormal };
        _thread.Start();
        started.Wait(); // from here on, set-up from other threads is queued for the bus thread
        started.Dispose();
    }

    /// <summary>A failed cycle; the same failure again is reported once a second, with how many were left out.</summary>
    private void Failed(IOException ex)
    {
        var now = time.GetTimestamp();
        var report = ex.Message != _lastFailure || time.GetElapsedTime(_lastFailureReported, now) >= RepeatedFailureReport;
        robot.CycleFailed(ex, report, report ? _failuresLeftOut : 0);
        if (report)
        {
            (_lastFailure, _lastFailureReported, _failuresLeftOut) = (ex.Message, now, 0);
        }
        else
        {
            _failuresLeftOut++;
        }
    }

    public void Stop()
    {
        _stopping = true;
        _thread?.Join();
        _thread = null;
    }

    // Optimized once, before the first cycle: a loop that runs for the whole session would otherwise start as quick
    // (tier-0) code and be replaced on the stack once it had looped long enough, a synchronous compile on this thread.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Loop()
    {
        var period = (long)(options.MinimumCyclePeriod.TotalSeconds * time.TimestampFrequency);
        var afterFirstCycle = false;
        var compiledMethods = 0L;
        var compileTime = TimeSpan.Zero;
        while (!_stopping)
        {
            var start = time.GetTimestamp();
            try
            {
                robot.RunCycle();
                if (_lastFailure is not null)
                {
                    robot.Slot.LinkWorks();
                    _lastFailure = null; // the link works again: its next failure is news
                }
            }
            catch (IOException ex)
            {
                Failed(ex);
                Thread.Sleep(PauseAfterFailure);
            }

            if (!afterFirstCycle)
            {
                afterFirstCycle = true;
                compiledMethods = JitInfo.GetCompiledMethodCount(currentThread: true);
                compileTime = JitInfo.GetCompilationTime(currentThread: true);
            }

            while (period > 0 && time.GetTimestamp() - start < period && !_stopping)
            {
                Thread.SpinWait(50);
            }
        }

        if (afterFirstCycle)
        {
            MethodsCompiledAfterFirstCycle = JitInfo.GetCompiledMethodCount(currentThread: true) - compiledMethods;
            CompileTimeAfterFirstCycle = JitInfo.GetCompilationTime(currentThread: true) - compileTime;
        }
    }
}
