using System.Runtime;
using System.Runtime.CompilerServices;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Simulation.Native;

namespace RobotControl.Simulation;

/// <summary>Serving the virtual bus on a real byte link (a pty) in real time.</summary>
public sealed unsafe partial class VirtualRobot
{
    /// <summary>
    /// Serves the bus on <paramref name="port"/> (a pty master or any byte link) in real time until cancelled: bytes
    /// from the port go to the modules, their replies back, and simulated time follows the wall clock.
    /// </summary>
    /// <remarks>
    /// Optimized once, before serving starts: as quick (tier-0) code, this loop was replaced on the stack after about
    /// 1–2 s of serving by a synchronous compile of 17–23 ms on this thread, during which no module answered; the host
    /// saw a bus cycle of over 10 ms and tripped (docs/perf/realtime.md).
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public void Serve(IByteLink port, CancellationToken cancellationToken)
    {
        ArgumentNullException.ThrowIfNull(port);
        var buffer = new byte[4096];
        var start = System.Diagnostics.Stopwatch.GetTimestamp();
        var origin = _nowUs;
        var pty = port as PseudoTerminal;
        var last = start;
        var lastCpu = Environment.CpuUsage.TotalTime;
        var afterFirstTurn = false;
        var compiledMethods = 0L;
        var compileTime = TimeSpan.Zero;
        while (!cancellationToken.IsCancellationRequested)
        {
            var now = System.Diagnostics.Stopwatch.GetTimestamp();
            var cpu = Environment.CpuUsage.TotalTime;
            if (now - last > LongestServeGap.Ticks * System.Diagnostics.Stopwatch.Frequency / TimeSpan.TicksPerSecond)
            {
                LongestServeGap = System.Diagnostics.Stopwatch.GetElapsedTime(last, now);
                LongestServeGapAt = System.Diagnostics.Stopwatch.GetElapsedTime(start, last);
                LongestServeGapCpu = cpu - lastCpu;
            }

            (last, lastCpu) = (now, cpu);
            RunPosted(); // modules plugged in or power-cycled from another thread
            if (pty is not null)
            {
                FollowLineBaud(pty.ClientBaud); // the host re-opened its port at a new baud (after a baud change)
            }

            var n = port.Read(buffer, TimeSpan.FromMicroseconds(200));
            if (n > 0)
            {
                if (pty is not null)
                {
                    FollowLineBaud(pty.ClientBaud); // a client sets its baud before it writes: these bytes run at it
                }

                HostWrite(buffer.AsSpan(0, n));
            }

            // Follow the wall clock in steps of at most 1 ms, handing replies out as soon as they are complete. When
            // the simulation cannot keep up, it slips (simulated time runs slower) rather than answer late.
            var wall = origin + (long)System.Diagnostics.Stopwatch.GetElapsedTime(start).TotalMicroseconds;
            if (wall - _nowUs > MaxRealTimeLagUs)
            {
                origin -= wall - _nowUs - MaxRealTimeLagUs;
                SlippedTime += TimeSpan.FromTicks((wall - _nowUs - MaxRealTimeLagUs) * 10);
                wall = _nowUs + MaxRealTimeLagUs;
            }

            do
            {
                AdvanceTo(Math.Min(wall, _nowUs + 1000));
                var m = TakeHostBytes(buffer);
                if (m > 0)
                {
                    port.Write(buffer.AsSpan(0, m));
                }
            }
            while (_nowUs < wall && !cancellationToken.IsCancellationRequested);
            if (!afterFirstTurn)
            {
                afterFirstTurn = true;
                compiledMethods = JitInfo.GetCompiledMethodCount(currentThread: true);
                compileTime = JitInfo.GetCompilationTime(currentThread: true);
            }
        }

        if (afterFirstTurn)
        {
            MethodsCompiledWhileServing = JitInfo.GetCompiledMethodCount(currentThread: true) - compiledMethods;
            CompileTimeWhileServing = JitInfo.GetCompilationTime(currentThread: true) - compileTime;
        }
    }

    /// <summary>The baud the simulated line runs at now (it follows the client's pty setting when served on a pty).</summary>
    public int LineBaud => (int)Math.Round(10e6 / _byteUs);

    private void FollowLineBaud(int baud)
    {
        if (baud > 0 && baud != LineBaud)
        {
            FirmwareHost.Check(FirmwareHost.BusSetBaud(_bus, (uint)baud), "rcfw_bus_set_baud");
            _byteUs = 10e6 / baud;
        }
    }

    /// <summary>Wall-clock time the real-time simulation (<see cref="Serve"/>) fell behind and skipped.</summary>
    public TimeSpan SlippedTime { get; private set; }

    /// <summary>
    /// The longest wall-clock time between two turns of <see cref="Serve"/>'s loop (a turn waits up to 200 us for bytes,
    /// then simulates up to now): longer than about 1 ms, the simulator was not running (preempted, paused, stalled).
    /// </summary>
    public TimeSpan LongestServeGap { get; private set; }

    /// <summary>When the <see cref="LongestServeGap"/> began, wall-clock time after serving started.</summary>
    public TimeSpan LongestServeGapAt { get; private set; }

    /// <summary>CPU time the process used during the <see cref="LongestServeGap"/>: about the gap, it was busy; about 0, it was not running.</summary>
    public TimeSpan LongestServeGapCpu { get; private set; }

    /// <summary>Methods the JIT compiled on the serving thread after its first turn of <see cref="Serve"/>; known once it has returned.</summary>
    public long MethodsCompiledWhileServing { get; private set; }

    /// <summary>Time the serving thread spent in the JIT after its first turn (see <see cref="MethodsCompiledWhileServing"/>).</summary>
    public TimeSpan CompileTimeWhileServing { get; private set; }
}
