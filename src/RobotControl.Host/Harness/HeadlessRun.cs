using System.Globalization;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Model;
using RobotControl.Host.Realtime;
using RobotControl.Host.Recording;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Events;
using RobotControl.Robot.Control;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;
using RobotControl.Simulation.Bus;

namespace RobotControl.Host.Harness;

/// <summary>
/// The headless run: brings a <see cref="RobotSession"/> up from a graph file (the virtual robot running the real
/// module firmware on a virtual clock, or the graph's transport in real time), runs the control loop for a duration
/// while measuring tick times, deadline misses and tracking error, and reports bus statistics and faults.
/// Deterministic on the virtual robot (<see cref="VirtualSchedule"/>): the same graph, duration, faults and seed give
/// the same report (tick times apart, which are measured CPU time).
/// </summary>
public static class HeadlessRun
{
    private static readonly TimeSpan PollInterval = TimeSpan.FromMilliseconds(10);

    /// <summary>Runs <paramref name="options"/> with plug-in types from <paramref name="catalog"/>.</summary>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">The graph names no robot, or the robot cannot be brought up.</exception>
    public static RunReport Run(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(catalog);
        return options.Virtual ? RunVirtual(options, catalog, progress, null) : RunRealTime(options, catalog, progress, null);
    }

    /// <summary>A virtual run with measurement hooks (benchmarks): a wrapper around the bus link, and one around each tick.</summary>
    internal static RunReport RunVirtual(RunOptions options, PluginCatalog catalog, VirtualRunHooks hooks) => RunVirtual(options, catalog, null, hooks);

    /// <summary>Joint angles per arm that the graph will command first (the initial values on the wires into the robot node).</summary>
    public static IReadOnlyList<double[]> InitialCommand(LoadedGraph loaded) => RobotSession.InitialCommand(loaded);

    private static RunReport RunVirtual(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress, VirtualRunHooks? hooks)
    {
        TrackingMeter? meter = null;
        RecordingTap? tap = null;
        using var session = RobotSession.Open(
            new SessionOptions { GraphPath = options.GraphPath, Seed = options.Seed, SettingOverrides = options.SettingOverrides, WrapLink = hooks?.WrapLink, Observer = (node, port) => Meter(node, port, options, out meter, out tap) },
            catalog);
        using var recorder = Record(session, tap, options);
        var bus = session.Robot;
        using var events = bus.Events.Subscribe(fromStart: true); // the run's report lists every event since discovery
        var sim = session.Simulation!;
        var clock = session.Clock;
        var faults = new List<FaultEntry>();
        DrainEvents(events, TimeSpan.Zero, faults); // discovery problems, once, at time 0
        var begin = clock.GetTimestamp();
        foreach (var reset in options.Inject.Resets)
        {
            sim.ScheduleReset(ResolveModule(session.Graph.Robot!, reset.Module), sim.Elapsed + reset.At);
        }

        foreach (var silent in options.Inject.TimedFaults.Where(f => f.Kind == TimedFaultKind.Silent))
        {
            sim.ScheduleTransmitBreak(ResolveModule(session.Graph.Robot!, silent.Target), sim.Elapsed + silent.At); // as the console does
        }

        if (options.Inject.BitErrorRate > 0)
        {
            sim.WireFaults = new WireFaults { BitErrorRate = options.Inject.BitErrorRate };
        }

        var safetyFaults = new SafetyFaultSchedule(options.Inject.TimedFaults, sim, bus, session.Graph, begin, clock.TimestampFrequency);
        var around = hooks?.AroundTick;
        PressPedal(session, begin, faults, recorder);
        var surgeon = new ReEngagement(session.Supervisor, clock, options.ReEngageAfter, ReEngagement.PedalWired(session.Graph));
        var loop = session.Loop;
        var ticks = (long)Math.Round(options.Duration.TotalSeconds * loop.RateHz);
        var progressEvery = Math.Max(1, (long)Math.Round(options.ProgressInterval.TotalSeconds * loop.RateHz));
        var reported = 0L;
        var stopper = new FaultStop(bus, options.ContinueOnFault, options.Stop, session.Supervisor);
        using var operatorStop = OperatorStop(options, session.Supervisor, recorder);
        using var motorsFirst = MotorsOffAtStop(options, session);
        session.RunVirtual(
            ticks,
            () =>
            {
                recorder?.KeepUpWithVirtualTime();
                surgeon.Poll();
                if (loop.TickCount - reported >= progressEvery || loop.TickCount >= ticks)
                {
                    reported = loop.TickCount;
                    var elapsed = clock.GetElapsedTime(begin);
                    DrainEvents(events, elapsed, faults);
                    progress?.Invoke(Progress(loop, meter!, elapsed, options.Duration, faults.Count + session.Graph.Program.FaultCount, bus.Faults.ToString(), session.Supervisor));
                }
            },
            safetyFaults.Remaining == 0 ? around : (l, at) =>
            {
                safetyFaults.BeforeTick(at);
                if (around is null)
                {
                    l.Step();
                }
                else
                {
                    around(l, at);
                }

                safetyFaults.AfterTick(at);
            },
            stopper.ShouldStop,
            options.TickCost);
        hooks?.AfterRun?.Invoke(session);
        var elapsed = clock.GetElapsedTime(begin);
        var check = session.Stop(); // motors off and read back first; the recording's end after
        return Finish(stopper, check, loop, meter!, elapsed, session, events, faults, surgeon.Presses) with { Recording = recorder?.Stop() };
    }

    /// <summary>Starts the session's recording (<see cref="RunOptions.Record"/>) on the tap built with the loop; null without one.</summary>
    private static SessionRecorder? Record(RobotSession session, RecordingTap? tap, RunOptions options) =>
        options.Record is { } record && tap is not null ? SessionRecorder.Start(session, tap, record) : null;

    /// <summary>A stop request (Ctrl+C, SIGTERM) switches the motors off at once, from the signal's own thread: the rest of the stop follows (<see cref="RobotSession.StopMotorsNow"/>).</summary>
    private static CancellationTokenRegistration MotorsOffAtStop(RunOptions options, RobotSession session) =>
        options.Stop.Register(() => session.StopMotorsNow("stop requested: motors off"));

    /// <summary>The command line's and the link's E-STOP (<see cref="RunOptions.EmergencyStop"/>, <see cref="RunOptions.LinkEmergencyStop"/>) go to the supervisor, as any operator E-STOP.</summary>
    private static OperatorStops OperatorStop(RunOptions options, SafetySupervisor supervisor, SessionRecorder? recorder) =>
        new(Register("cli", "E-STOP from the command line", supervisor, recorder, options.EmergencyStop), Register("link", "E-STOP from the surgeon's station", supervisor, recorder, options.LinkEmergencyStop));

    private static CancellationTokenRegistration Register(string source, string reason, SafetySupervisor supervisor, SessionRecorder? recorder, CancellationToken token) =>
        token.Register(() =>
        {
            supervisor.EmergencyStop(source, reason);
            recorder?.OperatorCommand(source, "E-STOP");
        });

    /// <summary>
    /// Without a pedal wired to the robot node (the shipped graphs), the harness is the operator and holds the pedal
    /// down for the run; with one, the pedal moves the run level (<see cref="SafetySupervisor"/>). On the wall clock
    /// the press runs on the bus thread between cycles. A refused press is reported in the run's faults and the run goes
    /// on: after a trip that came first (a stalled machine at start) at E_STOP, holding; at PEDAL_UP (a module silent for
    /// a moment) the harness presses again as after a soft trip.
    /// </summary>
    private static void PressPedal(RobotSession session, long begin, List<FaultEntry> faults, SessionRecorder? recorder)
    {
        session.Supervisor.SetOrigin(begin);
        if (ReEngagement.PedalWired(session.Graph))
        {
            return;
        }

        try
        {
            recorder?.OperatorCommand("harness", "pedal down");
            session.Supervisor.PedalDown("harness");
        }
        catch (Exception ex) when (ex is InvalidOperationException or IOException)
        {
            // Refused (a trip came first; a module silent for a moment on a loaded machine; the link failed): the run goes
            // on and its report says so; at PEDAL_UP the harness presses again as after a soft trip (ReEngagement).
            faults.Add(new FaultEntry(0, "harness", $"the pedal was not pressed: {ex.Message}"));
        }
    }

    /// <summary>A real-time run with measurement hooks (benchmarks): a wrapper around the bus link, and one call after the run.</summary>
    internal static RunReport RunRealTime(RunOptions options, PluginCatalog catalog, VirtualRunHooks hooks) => RunRealTime(options, catalog, null, hooks);

    private static RunReport RunRealTime(RunOptions options, PluginCatalog catalog, Action<RunProgress>? progress, VirtualRunHooks? hooks)
    {
        if (!options.Inject.IsNone)
        {
            throw new InvalidOperationException("--inject applies to the virtual robot only (add --virtual)");
        }

        TrackingMeter? meter = null;
        RecordingTap? tap = null;
        using var session = RobotSession.Open(
            new SessionOptions { GraphPath = options.GraphPath, Virtual = false, Transport = options.Transport, SettingOverrides = options.SettingOverrides, WrapLink = hooks?.WrapLink, Observer = (node, port) => Meter(node, port, options, out meter, out tap) },
            catalog);
        using var recorder = Record(session, tap, options);
        var bus = session.Robot;
        using var events = bus.Events.Subscribe(fromStart: true); // the run's report lists every event since discovery
        var loop = session.Loop;
        var clock = session.Clock;
        var faults = new List<FaultEntry>();
        DrainEvents(events, TimeSpan.Zero, faults); // discovery problems, once, at time 0
        var stopper = new FaultStop(bus, options.ContinueOnFault, options.Stop, session.Supervisor);
        using var operatorStop = OperatorStop(options, session.Supervisor, recorder);
        using var motorsFirst = MotorsOffAtStop(options, session);
        var nextProgress = options.ProgressInterval;
        StopCheck check;
        var threads = options.Threads ?? RealtimeThreads.Default;
        var gcBefore = System.Runtime.GCSettings.LatencyMode;
        System.Runtime.GCSettings.LatencyMode = options.RealtimeGcLatency;
        using var gcRestore = new RestoreOnDispose(() => System.Runtime.GCSettings.LatencyMode = gcBefore);
        session.StartRealtime(threads); // warm-up, homing, motors on: the run's time starts when the threads do
        var begin = clock.GetTimestamp();
        PressPedal(session, begin, faults, recorder);
        var surgeon = new ReEngagement(session.Supervisor, clock, options.ReEngageAfter, ReEngagement.PedalWired(session.Graph));
        try
        {
            while (clock.GetElapsedTime(begin) < options.Duration && loop.ThreadFailure is null && !stopper.ShouldStop())
            {
                // Short sleeps: a fault or a stop request is acted on within a few milliseconds.
                Thread.Sleep(PollInterval);
                surgeon.Poll();
                var now = clock.GetElapsedTime(begin);
                if (now >= nextProgress || now >= options.Duration)
                {
                    nextProgress += options.ProgressInterval;
                    DrainEvents(events, now, faults);
                    progress?.Invoke(Progress(loop, meter!, now, options.Duration, faults.Count + session.Graph.Program.FaultCount, bus.Faults.ToString(), session.Supervisor));
                }
            }
        }
        finally
        {
            hooks?.AfterRun?.Invoke(session);
            check = session.Stop();
        }

        var elapsed = clock.GetElapsedTime(begin);
        if (loop.ThreadFailure is { } failure)
        {
            faults.Add(new FaultEntry(elapsed.TotalSeconds, "harness", $"control loop failed: {failure.Message}"));
        }

        return Finish(stopper, check, loop, meter!, elapsed, session, events, faults, surgeon.Presses) with
        {
            Scheduling = $"{threads.Outcome}; GC {options.RealtimeGcLatency}{(session.CpuLatency is { } latency ? "; " + latency : "")}",
            Compiled = new CompiledAfterStart(loop.MethodsCompiledAfterFirstTick, loop.CompileTimeAfterFirstTick, bus.MethodsCompiledAfterFirstCycle, bus.CompileTimeAfterFirstCycle),
            Recording = recorder?.Stop(),
        };
    }

    /// <summary>The report, with how the run ended and what the modules said after the motors were switched off.</summary>
    private static RunReport Finish(FaultStop stopper, StopCheck check, ControlLoop loop, TrackingMeter meter, TimeSpan elapsed, RobotSession session, RobotEventSubscription events, List<FaultEntry> faults, int reEngagements)
    {
        DrainEvents(events, elapsed, faults);
        if (stopper.Fault is { } fault)
        {
            faults.Add(new FaultEntry(elapsed.TotalSeconds, "harness", $"robot fault, run stopped commanding: {fault}"));
        }

        if (!check.TorqueOff)
        {
            faults.Add(new FaultEntry(elapsed.TotalSeconds, "harness", $"after the stop, torque still on at module(s) [{string.Join(", ", check.TorqueOn)}], no answer from [{string.Join(", ", check.Unreachable)}]"));
        }

        return Report(loop, meter, elapsed, session, faults, reEngagements) with { Interrupted = stopper.Interrupted, StoppedOnFault = stopper.Fault, Stop = check };
    }

    /// <summary>The loop's observers: the tracking meter, then the recording's tap when the run records.</summary>
    private static TrackingMeter Meter(RobotNode node, IRobotPort port, RunOptions options, out TrackingMeter meter, out RecordingTap? tap)
    {
        tap = options.Record is null ? null : new RecordingTap(node, port);
        return meter = new TrackingMeter(node, port) { Next = tap };
    }

    private static RunProgress Progress(ControlLoop loop, TrackingMeter meter, TimeSpan elapsed, TimeSpan duration, int faults, string robotFaults, SafetySupervisor supervisor)
    {
        var trips = supervisor.TripCount;
        return new(elapsed, duration, loop.TickCount, loop.Statistics.DeadlineMisses, meter.RmsMm, meter.LastErrorMm.Max(), faults, robotFaults)
        {
            RunLevel = supervisor.Level.Name(),
            Trips = trips,
            LastTrip = trips == 0 ? null : supervisor.Trips[^1].ToString(), // the list is copied only when there is a trip to name
        };
    }

    private static RunReport Report(ControlLoop loop, TrackingMeter meter, TimeSpan elapsed, RobotSession session, List<FaultEntry> faults, int reEngagements)
    {
        var loaded = session.Graph;
        var bus = session.Robot;
        var all = faults
            .Concat(loaded.Program.Faults.Select(f => new FaultEntry(f.Time.TotalSeconds, f.Instance, f.Message)))
            .OrderBy(f => f.TimeSeconds)
            .ToList();
        if (loaded.RobotNode is { RejectedSetpoints: > 0 } node)
        {
            all.Add(new FaultEntry(elapsed.TotalSeconds, RobotNode.InstanceName, $"{node.RejectedSetpoints} non-finite setpoint vectors refused"));
        }

        var totals = bus.Client.Totals(bus.Controllers.Select(c => c.Id));
        var stats = loop.Statistics;
        return new RunReport(
            elapsed.TotalSeconds,
            loop.TickCount,
            stats.DeadlineMisses,
            stats.MedianUs,
            stats.P99Us,
            stats.MaxUs,
            meter.RmsMm,
            meter.MaxMm,
            new BusReport(totals.Frames, totals.CrcErrors, totals.Timeouts, totals.Retries, bus.Client.LateReplies),
            all,
            SafetyReport.Of(session.Supervisor, elapsed.TotalSeconds, reEngagements));
    }

    private static void DrainEvents(RobotEventSubscription events, TimeSpan at, List<FaultEntry> faults)
    {
        while (events.TryRead(out var e))
        {
            faults.Add(new FaultEntry(at.TotalSeconds, "robot", e.Message.Trim()));
        }
    }

    /// <summary>
    /// The bus ID of the module an <c>--inject</c> fault names (<c>arm.location</c>, its name or its ID); a refusal names
    /// <paramref name="asked"/> as what asked (another command's word for it, e.g. bus-sim's <c>connect</c>).
    /// </summary>
    /// <exception cref="FormatException">No such module (the message lists them).</exception>
    public static byte ResolveModule(RobotDefinition robot, string module, string asked = "--inject")
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(module);
        if (byte.TryParse(module, NumberStyles.None, CultureInfo.InvariantCulture, out var id) && robot.Modules.ById(id) is not null)
        {
            return id;
        }

        foreach (var m in robot.Modules.Modules)
        {
            var arm = m.Arm >= 0 && m.Arm < robot.Arms.Count ? robot.Arms[m.Arm].Name : "";
            if (string.Equals($"{arm}.{m.Location}", module, StringComparison.OrdinalIgnoreCase) || string.Equals(m.Name, module, StringComparison.OrdinalIgnoreCase))
            {
                return m.Id;
            }
        }

        throw new FormatException($"{asked}: no module '{module}' (known: {string.Join(", ", robot.Modules.Modules.Select(m => $"{(m.Arm >= 0 && m.Arm < robot.Arms.Count ? robot.Arms[m.Arm].Name : "?")}.{m.Location} (id {m.Id})"))})");
    }

    /// <summary>Runs an action when disposed (puts a process-wide setting back after a run, however it ends).</summary>
    private sealed class RestoreOnDispose(Action restore) : IDisposable
    {
        public void Dispose() => restore();
    }
}

/// <summary>The run's operator E-STOP registrations (command line, link), undone together.</summary>
internal readonly record struct OperatorStops(CancellationTokenRegistration CommandLine, CancellationTokenRegistration Link) : IDisposable
{
    public void Dispose()
    {
        CommandLine.Dispose();
        Link.Dispose();
    }
}
