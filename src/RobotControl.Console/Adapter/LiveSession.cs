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
/// by the session layer) run on the robot's one bus cycle. On the virtual robot the session layer's
/// <see cref="VirtualSchedule"/> runs the cycles and ticks the loop on the session thread, paced to the wall clock; on a
/// real bus the session layer's bus thread and loop thread run them (<see cref="RobotSession.StartBus"/>). The console's
/// commands run in the robot's slot between cycles (<see cref="CommandQueue"/>); an emergency stop goes to the
/// supervisor directly. It has no bus client of its own: what it shows of the modules is what the robot core found
/// (status, resets, watchdog, torque read back, motor errors), published with the run status every 100 ms by a
/// thread of its own. The ring is fed by the loop's tick observer.
/// </summary>
public sealed partial class LiveSession : IConsoleSession
{
    private static readonly TimeSpan PublishEvery = TimeSpan.FromMilliseconds(100);

    /// <summary>Cycles between two reads of one module's torque and motor errors (the modules in turn).</summary>
    private const int DetailPollCycles = 50;

    /// <summary>How many times a module's parameters are tried before they are left unknown.</summary>
    private const int ParameterReadTries = 5;

    private readonly RobotSession _session;
    private readonly TimeProvider _clock;
    private readonly RobotDefinition _robot;
    private readonly BusRobot _bus;
    private readonly SafetySupervisor _supervisor;
    private readonly RingRecorder _recorder;
    private readonly CommandQueue _commands;
    private readonly Session.EventLog _events = new();
    private readonly RobotControl.Robot.Events.RobotEventSubscription _robotEvents;
    private readonly System.Collections.Concurrent.ConcurrentDictionary<int, string> _names = [];
    private readonly System.Collections.Concurrent.ConcurrentDictionary<(int Module, int Channel, string Key), double> _parameters = [];
    private readonly System.Collections.Concurrent.ConcurrentQueue<RobotController> _pendingReads = new();
    private readonly Dictionary<int, int> _parameterTries = [];
    private readonly TickStatistics _busTiming = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly Lock _closeLock = new();
    private readonly Lock _logGate = new();
    private readonly Host.Realtime.RealtimeThreads _threads;
    private readonly Thread _thread;
    private readonly Thread _publisher;
    private readonly long _begin;
    private Task<CommandResult>? _parameterRead;
    private volatile SessionStatus _statusView;
    private volatile IReadOnlyList<ControllerView> _controllersView = [];
    private volatile string _state = "starting";
    private int _levelsLogged;
    private int _tripsLogged;
    private long _tickAllocatedBytes;
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
    public LiveSession(LiveSessionOptions options)
    {
        ArgumentNullException.ThrowIfNull(options);
        _threads = options.Threads ?? Host.Realtime.RealtimeThreads.Default;
        var slot = new ObserverSlot();
        var faults = new ConsoleFaults(options.Inject, options.Virtual);
        _session = RobotSession.Open(
            new SessionOptions { GraphPath = options.GraphPath, Virtual = options.Virtual, Seed = options.Seed, Transport = options.Transport, Observer = (_, _) => slot, Robot = new BusRobotOptions { DetailPollCycles = DetailPollCycles } },
            options.Catalog);
        _robot = _session.Connection.Definition!;
        _bus = _session.Robot;
        _supervisor = _session.Supervisor;
        _clock = _session.Clock;
        _begin = _clock.GetTimestamp();
        _commands = new CommandQueue(_bus.Slot);
        _robotEvents = _bus.Events.Subscribe();
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
        _publisher = new Thread(PublishUntilStopped) { Name = "console session (status)", IsBackground = true };
        _thread.Start();
        _publisher.Start();
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
        Timing(_session.IsVirtual ? "bus cycle (write, read, publish, check, between cycles)" : "bus cycle (timed on the virtual robot only)", _busTiming),
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

            _commands.Close();
            _stop.Cancel();
            _thread.Join();
            var stop = _session.Stop(); // loop and bus thread off, motors off through the robot's state machine (or written off directly), every module read back
            _publisher.Join();
            var last = BuildStatus();
            _events.Add(Now, "session", $"stopped: {stop.Summary}");
            _end = new SessionEnd(last with { Session = "stopped", TorqueOn = stop.TorqueOn.Count > 0 }, stop, _events.After(0), Timings);
            return _end;
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _ = Close();
        _robotEvents.Dispose();
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
        // The session layer's schedule runs the robot's cycle and the loop ticks due on the virtual clock, and the
        // work between cycles (the console's commands); the thread sleeps whenever the virtual clock gets ahead of the
        // wall clock, so the virtual robot runs in real time.
        var wall = Stopwatch.StartNew();
        var cycleBegin = Stopwatch.GetTimestamp();
        _session.RunVirtual(long.MaxValue, () =>
        {
            _busTiming.Record(Stopwatch.GetTimestamp() - cycleBegin);
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

    /// <summary>
    /// A real bus: the session layer starts the robot's bus thread and the loop thread, as a run does (one bus loop);
    /// this thread waits for the stop, or for the loop to fail.
    /// </summary>
    private void RunRealTime()
    {
        _session.StartBus(_threads); // code compiled, wake-up latency held until the session's stop, as in a run
        _events.Add(Now, "session", $"threads: {_threads.Outcome}{(_session.CpuLatency is { } latency ? "; " + latency : "")}");
        var loop = _session.Loop;
        while (!_stop.Token.WaitHandle.WaitOne(PublishEvery) && loop.ThreadFailure is null)
        {
        }

        if (loop.ThreadFailure is { } failure)
        {
            throw new InvalidOperationException($"control loop failed: {failure.Message}", failure);
        }
    }

    /// <summary>The status thread: events, run levels, parameter reads and snapshots every <see cref="PublishEvery"/> until the stop.</summary>
    private void PublishUntilStopped()
    {
        do
        {
            PublishOnce();
        }
        while (!_stop.Token.WaitHandle.WaitOne(PublishEvery));

        PublishOnce();
    }

    private void PublishOnce()
    {
        while (_robotEvents.TryRead(out var e))
        {
            _events.Add(Now, "robot", e.Message);
        }

        LogSupervisor();
        ReadPendingParameters();
        _statusView = BuildStatus();
        PublishControllers();
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

        return lines;
    }

    /// <summary>Copies the supervisor's new run-level changes and trips into the event log.</summary>
    private void LogSupervisor()
    {
        lock (_logGate)
        {
            LogSupervisorLocked();
        }
    }

    private void LogSupervisorLocked()
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

    /// <summary>The bus page's modules and motors, as the robot core last found them.</summary>
    private void PublishControllers()
    {
        var list = new List<ControllerView>();
        foreach (var c in _bus.Controllers)
        {
            var status = (HardwareErrors)c.HardwareErrorStatus;
            var motors = c.Motors.Select(m => new MotorView(
                m.Config.FullName,
                m.Config.Name,
                m.Config.Channel,
                m.PositionRad * 180 / Math.PI,
                m.Config.OutputMinRad * 180 / Math.PI,
                m.Config.OutputMaxRad * 180 / Math.PI,
                m.CurrentA,
                m.Pwm,
                m.IsManual,
                m.TorqueReadBack ?? false,
                m.Errors is { } errors ? Names(errors) : [],
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
                ResetCause(c.LastResetCause),
                c.Resets,
                c.BusWatchdogMs switch { < 0 => "not read yet", 0 => "off", var ms => $"{ms} ms" } + (status.HasAny(HardwareErrors.BusWatchdog) ? ", TRIPPED" : string.Empty),
                Names(status),
                motors));
        }

        _controllersView = list;
    }

    /// <summary>Names of the set bits of <paramref name="bits"/>, as the control table names them.</summary>
    private static string[] Names(HardwareErrors bits) => bits.IsNone ? [] : bits.ToString().Split(", ");

    /// <summary>A reset cause in words, as the control table names it.</summary>
    private static string ResetCause(int cause) =>
        cause == 0 ? "none since connected"
        : Bus.Protocol.ControlTable.Firmware.Codes("reset_cause").TryGetValue(cause, out var name) ? name : $"cause {cause}";

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
