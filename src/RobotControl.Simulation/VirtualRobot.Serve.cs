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
        Serving.Start(start);
        while (!cancellationToken.IsCancellationRequested)
        {
            Serving.Turn(System.Diagnostics.Stopwatch.GetTimestamp());
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
                Serving.SlippedTime += TimeSpan.FromTicks((wall - _nowUs - MaxRealTimeLagUs) * 10);
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
            Serving.FirstTurnDone();
        }

        Serving.Stop();
    }

    /// <summary>The baud the simulated line runs at now (it follows the client's pty setting when served on a pty).</summary>
    public int LineBaud => (int)Math.Round(10e6 / _byteUs);

    /// <summary>Moves the simulated line (every module and the host's end) to <paramref name="baud"/>.</summary>
    internal void SetLineBaud(int baud) => FollowLineBaud(baud);

    private void FollowLineBaud(int baud)
    {
        if (baud > 0 && baud != LineBaud)
        {
            FirmwareHost.Check(FirmwareHost.BusSetBaud(_bus, (uint)baud), "rcfw_bus_set_baud");
            _byteUs = 10e6 / baud;
        }
    }

    /// <summary>How <see cref="Serve"/> kept up with the wall clock.</summary>
    public ServeStatistics Serving { get; } = new();
}
