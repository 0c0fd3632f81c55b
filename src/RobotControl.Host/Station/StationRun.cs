using System.Diagnostics;
using RobotControl.Host.Realtime;
using RobotControl.Host.Session;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;

namespace RobotControl.Host.Station;

/// <summary>
/// A run of a graph that names no robot: one station of a graph split at its wires (docs/link.md), such as the
/// surgeon's station (Touch, homing, scaling, clutch, haptic walls, and the links to and from the robot station). Its
/// loop runs on the wall clock, with the real-time threads' scheduling, for the duration or until stopped. It drives
/// no motor: stopping it is ending the loop, and the robot station holds its arms when the link goes quiet (its
/// <c>master_timeout</c>), so it never needs this station to stop safely.
/// </summary>
public static class StationRun
{
    private static readonly TimeSpan PollInterval = TimeSpan.FromMilliseconds(10);
    private static readonly TimeSpan LoopStopWait = TimeSpan.FromSeconds(2);

    /// <summary>Runs the graph of <paramref name="options"/> (it names no robot) with plug-ins from <paramref name="catalog"/>.</summary>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">An option that needs a robot (<c>--virtual</c>, <c>--inject</c>, <c>--record</c>, <c>--transport</c>), or the graph names one.</exception>
    public static StationReport Run(Harness.RunOptions options, PluginCatalog catalog, Action<StationProgress>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(catalog);
        Refuse(options);
        var loaded = GraphFile.Load(options.GraphPath, catalog, TimeProvider.System, options.SettingOverrides);
        if (loaded.Robot is not null)
        {
            throw new InvalidOperationException($"{loaded.Path}: the graph names a robot file; it runs as a robot session, not as a station");
        }

        var loop = new ControlLoop(loaded.Program, TimeProvider.System, loaded.Document.LoopRateHz);
        var threads = options.Threads ?? RealtimeThreads.Default;
        _ = CodeWarmUp.Prepare(CodeWarmUp.CycleTypes(loaded.Program)); // the first ticks do not wait for the JIT
        var begin = Stopwatch.GetTimestamp();
        var interrupted = false;
        var stopped = true;
        try
        {
            threads.StartLoop(loop.Start); // no bus thread: the station has no robot
            var nextProgress = options.ProgressInterval;
            while (Stopwatch.GetElapsedTime(begin) < options.Duration && loop.ThreadFailure is null)
            {
                if (options.Stop.IsCancellationRequested)
                {
                    interrupted = true;
                    break;
                }

                Thread.Sleep(PollInterval);
                var now = Stopwatch.GetElapsedTime(begin);
                if (progress is not null && (now >= nextProgress || now >= options.Duration))
                {
                    nextProgress += options.ProgressInterval;
                    progress(new StationProgress(now, options.Duration, loop.TickCount, loop.Statistics.DeadlineMisses, loaded.Program.FaultCount));
                }
            }
        }
        finally
        {
            stopped = loop.Stop(LoopStopWait);
        }

        return StationReport.Of(loaded, loop, Stopwatch.GetElapsedTime(begin), interrupted, stopped, threads.Outcome);
    }

    private static void Refuse(Harness.RunOptions options)
    {
        var why = options switch
        {
            { Virtual: true } => "--virtual runs the virtual robot on a virtual clock; a station without a robot runs on the wall clock (leave --virtual out)",
            { Inject.IsNone: false } => "--inject injects faults into the virtual robot; a station without a robot has none",
            { Record: not null } => "--record records a robot session; a station without a robot is recorded by the robot station it links to",
            { Transport: not null } => "--transport opens the robot's bus; a station without a robot has none",
            _ => null,
        };
        if (why is not null)
        {
            throw new InvalidOperationException($"{options.GraphPath}: the graph names no robot file: {why}");
        }
    }
}

/// <summary>How far a station run is.</summary>
/// <param name="Elapsed">Wall-clock time since the loop started.</param>
/// <param name="Duration">How long it runs.</param>
/// <param name="Ticks">Ticks so far.</param>
/// <param name="DeadlineMisses">Ticks started late so far.</param>
/// <param name="PluginFaults">Plug-in faults so far.</param>
public sealed record StationProgress(TimeSpan Elapsed, TimeSpan Duration, long Ticks, long DeadlineMisses, int PluginFaults);
