using System.Diagnostics;
using RobotControl.Hardware.Model;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Kinematics.Urdf;
using RobotControl.Modules;
using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Runtime.Loop;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console's session: a <see cref="RobotSession"/> (graph, robot, bus, safety supervisor, control loop, brought up
/// by the session layer) run by one thread that owns the bus. It runs the bus cycles, applies the console's queued
/// commands between them, polls module status and publishes snapshots. On the virtual robot the session layer's
/// <see cref="VirtualSchedule"/> ticks the loop on that thread, paced to the wall clock; on a real bus the loop runs on
/// its own thread. The ring is fed by the loop's tick observer.
/// </summary>
public sealed partial class HeadlessSession : IConsoleSession
{
    private static readonly TimeSpan PublishEvery = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan PollEvery = TimeSpan.FromMilliseconds(200);

    /// <summary>How many times a module's parameters are tried before they are left unknown.</summary>
    private const int ParameterReadTries = 5;

    private readonly RobotSession _session;
    private readonly TimeProvider _clock;
    private readonly RobotDefinition _robot;
    private readonly BusRobot _bus;
    private readonly SafetySupervisor _supervisor;
    private readonly RingRecorder _recorder;
    private readonly CommandQueue _commands = new();
    private readonly Session.EventLog _events = new();
    private readonly Dictionary<int, string> _names = [];
    private readonly Dictionary<int, ModuleStatus> _status = [];
    private readonly Dictionary<(int Module, int Channel, string Key), double> _parameters = [];
    private readonly Queue<RobotController> _pendingReads = new();
    private readonly Dictionary<int, int> _parameterTries = [];
    private readonly TickStatistics _busTiming = new();
    private readonly TickStatistics _pollTiming = new();
    private readonly TickStatistics _commandTiming = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly Lock _closeLock = new();
    private readonly Host.Realtime.RealtimeThreads _threads;
    private readonly Thread _thread;
    private readonly long _begin;
    private volatile SessionStatus _statusView;
    private volatile IReadOnlyList<ControllerView> _controllersView = [];
    private volatile string _state = "starting";
    private int _levelsLogged;
    private int _tripsLogged;
    private long _tickAllocatedBytes;
    private int _pollNext;
    private int _found;
    private SessionEnd? _end;

    /// <summary>
    /// Brings the session up through the session layer (graph, robot, discovery, safety supervisor homing to
    /// PEDAL_UP with the motors on, control loop), reads the modules' parameters and starts the session thread.
    /// </summary>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">The graph names no robot, or the transport does not fit.</exception>
    /// <exception cref="IOException">The transport cannot be opened.</exception>
    /// <exception cref="FormatException">An injected fault is not one the console takes, or names no module.</exception>
    public HeadlessSession(HeadlessSessionOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        _threads = options.Threads ?? Host.Realtime.RealtimeThreads.Default;
        var slot = new ObserverSlot();
        var faults = new ConsoleFaults(options.Inject, options.Virtual);
        _session = RobotSession.Open(
            new SessionOptions { GraphPath = options.GraphPath, Virtual = options.Virtual, Seed = options.Seed, Transport = options.Transport, Observer = (_, _) => slot },
            options.Catalog);
        _robot = _session.Connection.Definition!;
        _bus = _session.Robot;
        _supervisor = _session.Supervisor;
        _clock = _session.Clock;
        _begin = _clock.GetTimestamp();
        try
        {
            faults.Schedule(_session.Simulation, _robot);
        }
        catch (FormatException)
        {
            _session.Dispose();
            throw;
        }
        _recorder = new RingRecorder(_session.Graph.Program, _session.Node, options.RingCapacity);
        slot.Target = _recorder;
        Transport = options.Virtual ? $"virtual:{Path.GetFileName(_robot.SourceFile)}" : options.Transport ?? _session.Graph.Document.Transport;
        Model = BuildModel();
        LogDiscovery(_session.Discovery);
        foreach (var c in _bus.Controllers.Where(c => c.Present))
        {
            _pendingReads.Enqueue(c); // read between the first cycles, one module at a time
        }

        LogSupervisor();
        _statusView = BuildStatus();
        PublishControllers();
        _thread = new Thread(Run) { Name = "console session (bus)", IsBackground = true, Priority = ThreadPriority.AboveNormal };
        _thread.Start();
    }

    /// <summary>The transport in use.</summary>
    public string Transport { get; }

    /// <inheritdoc />
    public SessionStatus Status => _statusView;

    /// <inheritdoc />
    public IReadOnlyList<ControllerView> Controllers => _controllersView;

    /// <inheritdoc />
    public SignalRing Signals => _recorder.Ring;

    /// <inheritdoc />
    public RobotModelView Model { get; }

    /// <inheritdoc />
    public IReadOnlyList<ComponentTiming> Timings =>
    [
        Timing($"control loop tick ({_session.Graph.Program.Order.Count} instances)", _session.Loop.Statistics),
        Timing("bus cycle (sync write + sync read)", _busTiming),
        Timing("module status poll", _pollTiming),
        Timing("console commands", _commandTiming),
    ];

    /// <summary>The loop (benchmarks read its statistics).</summary>
    internal ControlLoop Loop => _session.Loop;

    /// <inheritdoc />
    public IReadOnlyList<EventEntry> EventsAfter(long after) => _events.After(after);

    /// <inheritdoc />
    public SessionEnd Close()
    {
        lock (_closeLock)
        {
            if (_end is not null)
            {
                return _end;
            }

            _stop.Cancel();
            _thread.Join();
            _commands.Close();
            var last = BuildStatus();
            var stop = _session.Stop(); // loop off, motors off through the robot's state machine (or written off directly), every module read back
            _events.Add(Now, "session", $"stopped: {stop.Summary}");
            _end = new SessionEnd(last with { Session = "stopped", TorqueOn = stop.TorqueOn.Count > 0 }, stop, _events.After(0), Timings);
            return _end;
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _ = Close();
        _session.Dispose();
        _stop.Dispose();
    }

    private static ComponentTiming Timing(string name, TickStatistics s) => new(name, s.Count, s.MedianUs, s.P99Us, s.MaxUs);

    private double Now => _clock.GetElapsedTime(_begin).TotalSeconds;

    private void Run()
    {
        try
        {
            _state = "running";
            if (_session.IsVirtual)
            {
                RunVirtual();
            }
            else
            {
                RunRealTime();
            }
        }
#pragma warning disable CA1031 // the session thread reports what ended it in the status and the event log
        catch (Exception ex)
#pragma warning restore CA1031
        {
            _state = "failed";
            _events.Add(Now, "session", $"the session thread stopped: {ex.Message}");
            _statusView = BuildStatus();
            return;
        }

        _state = "stopped";
    }

    private void RunVirtual()
    {
        // The session layer's schedule runs bus cycles and the loop ticks due on the virtual clock; between cycles
        // the console's work runs, and the thread sleeps whenever the virtual clock gets ahead of the wall clock, so
        // the virtual robot runs in real time.
        var wall = Stopwatch.StartNew();
        var nextPublish = 0.0;
        var nextPoll = 0.0;
        var cycleBegin = Stopwatch.GetTimestamp();
        _session.RunVirtual(long.MaxValue, () =>
        {
            _busTiming.Record(Stopwatch.GetTimestamp() - cycleBegin);
            Between(ref nextPublish, ref nextPoll);
            var ahead = Now - wall.Elapsed.TotalSeconds;
            if (ahead > 0.002)
            {
                Thread.Sleep(TimeSpan.FromSeconds(ahead));
            }

            cycleBegin = Stopwatch.GetTimestamp();
        }, StepCountingAllocations, () => _stop.IsCancellationRequested);
    }

    /// <summary>One loop tick (the loop plus the ring recorder), counting what it allocates on this thread.</summary>
    private void StepCountingAllocations(ControlLoop loop, long timestamp)
    {
        var before = GC.GetAllocatedBytesForCurrentThread();
        loop.Step();
        Interlocked.Add(ref _tickAllocatedBytes, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    // Optimized once: this loop runs for the whole session, and tier-0 code would be replaced on the stack by a
    // synchronous compile on the bus thread once it had looped long enough, with the watchdogs armed.
    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveOptimization)]
    private void RunRealTime()
    {
        // The loop runs on its own thread; this thread owns the bus, so the console's commands run between cycles.
        _session.PrepareRealtime(_threads); // code compiled, wake-up latency held until the session's stop, as in a run
        var loop = _session.Loop;
        _threads.Start(prologue => prologue(), loop.Start); // this thread schedules itself, the loop thread its own
        _events.Add(Now, "session", $"threads: {_threads.Outcome}{(_session.CpuLatency is { } latency ? "; " + latency : "")}");
        var nextPublish = 0.0;
        var nextPoll = 0.0;
        try
        {
            while (!_stop.IsCancellationRequested && loop.ThreadFailure is null)
            {
                Between(ref nextPublish, ref nextPoll);
                var begin = Stopwatch.GetTimestamp();
                try
                {
                    _bus.RunCycle();
                }
                catch (IOException ex)
                {
                    _events.Add(Now, "bus", $"bus error: {ex.Message}");
                    Thread.Sleep(10);
                }

                _busTiming.Record(Stopwatch.GetTimestamp() - begin);
                while (Stopwatch.GetElapsedTime(begin) < TimeSpan.FromMilliseconds(1) && !_stop.IsCancellationRequested)
                {
                    Thread.SpinWait(50);
                }
            }
        }
        finally
        {
            loop.Stop();
        }

        if (loop.ThreadFailure is { } failure)
        {
            throw new InvalidOperationException($"control loop failed: {failure.Message}", failure);
        }
    }

    /// <summary>Work between bus cycles: commands, events, status poll, snapshots.</summary>
    private void Between(ref double nextPublish, ref double nextPoll)
    {
        var begin = Stopwatch.GetTimestamp();
        if (_commands.Drain() > 0)
        {
            _commandTiming.Record(Stopwatch.GetTimestamp() - begin);
            PublishControllers();
        }

        while (_bus.Events.TryDequeue(out var line))
        {
            _events.Add(Now, "robot", line.Message);
        }

        // Bus work is spread over the cycles (one module's reads at a time), so no gap between two cycles grows
        // beyond a few milliseconds while the motors are on.
        var now = Now;
        if (now >= nextPoll)
        {
            nextPoll = now + (PollEvery.TotalSeconds / Math.Max(1, _bus.Controllers.Count));
            begin = Stopwatch.GetTimestamp();
            if (_pendingReads.TryDequeue(out var unread))
            {
                TryReadParameters(unread);
            }
            else
            {
                PollNextModule();
            }

            _pollTiming.Record(Stopwatch.GetTimestamp() - begin);
        }

        if (now >= nextPublish)
        {
            nextPublish = now + PublishEvery.TotalSeconds;
            LogSupervisor();
            _statusView = BuildStatus();
            PublishControllers();
        }
    }

    /// <summary>Logs what discovery found and returns it as lines.</summary>
    private List<string> LogDiscovery(DiscoveryReport report)
    {
        _found = report.Present.Count;
        var lines = report.Lines().Select(l => l.Trim()).ToList();
        foreach (var line in lines)
        {
            _events.Add(Now, "discovery", line);
        }

        while (_bus.Events.TryDequeue(out _))
        {
            // Discovery's findings are logged above, from the report.
        }

        return lines;
    }

    private void ReadAllParameters()
    {
        foreach (var c in _bus.Controllers.Where(c => c.Present))
        {
            ReadParameters(c);
        }
    }

    /// <summary>Copies the supervisor's new run-level changes and trips into the event log.</summary>
    private void LogSupervisor()
    {
        var history = _supervisor.History;
        for (; _levelsLogged < history.Count; _levelsLogged++)
        {
            var h = history[_levelsLogged];
            _events.Add(Now, "safety", $"{h.From.Name()} -> {h.To.Name()} ({h.Source}): {h.Reason}");
        }

        var trips = _supervisor.Trips;
        for (; _tripsLogged < trips.Count; _tripsLogged++)
        {
            _events.Add(Now, "safety", $"trip: {trips[_tripsLogged]}");
        }
    }

    private SessionStatus BuildStatus()
    {
        var totals = _bus.Client.Totals(_bus.Controllers.Select(c => c.Id));
        var stats = _session.Loop.Statistics;
        var faults = _bus.Faults;
        var state = _state == "running" && _session.Node.Holding ? "holding (a plug-in faulted)" : _state;
        var faultNames = Enum.GetValues<RobotFaults>().Where(f => f != RobotFaults.None && faults.HasFlag(f)).Select(f => f.ToString())
            .Concat(_supervisor.Level == RunLevel.EStop ? _supervisor.Trips.Select(t => $"trip: {t}") : []);
        return new SessionStatus(
            _robot.Name,
            Path.GetFileName(_session.Graph.Path),
            Transport,
            _bus.Controllers.Count,
            _found,
            _session.Graph.Document.LoopRateHz,
            _session.Loop.TickCount,
            stats.DeadlineMisses,
            stats.MedianUs,
            stats.P99Us,
            stats.MaxUs,
            _session.IsVirtual ? Interlocked.Read(ref _tickAllocatedBytes) : null,
            Now,
            _supervisor.Level.Name(),
            _bus.State.ToString(),
            state,
            TorqueOn,
            [.. faultNames],
            _session.Graph.Program.FaultCount,
            new BusCounters(_bus.Cycles, totals.Frames, totals.CrcErrors, totals.Timeouts, totals.Retries));
    }

    private void PublishControllers()
    {
        var list = new List<ControllerView>();
        foreach (var c in _bus.Controllers)
        {
            var status = _status.TryGetValue(c.Id, out var s) ? s : ModuleStatus.Unknown(c.Motors.Count == 0 ? 1 : c.Motors.Max(m => m.Config.Channel) + 1);
            var motors = c.Motors.Select(m => new MotorView(
                m.Config.FullName,
                m.Config.Name,
                m.Config.Channel,
                m.PositionRad * 180 / Math.PI,
                m.Config.OutputMinRad * 180 / Math.PI,
                m.Config.OutputMaxRad * 180 / Math.PI,
                m.CurrentA,
                status.Pwm[m.Config.Channel],
                m.IsManual,
                status.Torque[m.Config.Channel],
                ModuleStatus.Names(status.MotorErrors[m.Config.Channel]),
                [.. MotorParameter.All.Select(p =>
                {
                    var (min, max) = p.Range(m.Config);
                    var value = _parameters.TryGetValue((c.Id, m.Config.Channel, p.Key), out var v) ? v : double.NaN;
                    return new ParameterSpec(p.Key, p.Label, p.Unit, value, p.FileValue(m.Config), min, max);
                })])).ToList();
            list.Add(new ControllerView(
                c.Id,
                _names.TryGetValue(c.Id, out var name) ? name : c.Name,
                c.Present,
                c.ModelNumber,
                c.FirmwareVersion,
                ModuleStatus.Cause(status.ResetCause),
                c.Resets,
                status.WatchdogMs == 0 ? "off" : $"{status.WatchdogMs} ms{(status.Errors.HasAny(HardwareErrors.BusWatchdog) ? ", TRIPPED" : string.Empty)}",
                ModuleStatus.Names(status.Errors),
                motors));
        }

        _controllersView = list;
    }

    /// <summary>True while the motors are driven (the robot layer is enabled).</summary>
    private bool TorqueOn => _bus.State == Robot.States.RobotState.Enabled;

    /// <summary>The 3D view's model: the host's URDF of the robot (both arms) and each arm's joints and signals.</summary>
    private RobotModelView BuildModel()
    {
        var urdf = UrdfExport.ToDocument(_robot).ToString();
        var arms = _robot.Arms.Select(a => new ArmView(
            a.Name,
            [.. _robot.Joints.Select(j => UrdfExport.JointName(a.Name, j.Name))],
            [.. _robot.Joints.Select(j => RingRecorder.PositionSignal(a.Name, j.Name))],
            [.. _robot.Joints.Select(j => RingRecorder.CommandSignal(a.Name, j.Name))])).ToList();
        return new RobotModelView(urdf, arms);
    }

    /// <summary>The loop's observer, given to the session layer before the recorder (which needs the loaded graph) exists.</summary>
    private sealed class ObserverSlot : ITickObserver
    {
        public RingRecorder? Target { get; set; }

        public void AfterTick(in TickContext context) => Target?.AfterTick(in context);
    }
}
