using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The live session's status thread: every <see cref="Every"/> until the stop it copies the robot's events (its own
/// subscription to the robot's event stream) and the supervisor's run levels into the event log, starts the next
/// module's parameter read, and publishes immutable snapshots of the run status and of the bus page's modules and
/// motors, as the robot core last found them.
/// <para>
/// Written by the status thread (the snapshots, the event subscription), by the constructor (the first snapshots), by
/// a command's completion (<see cref="PublishAfterCommand"/>, so that what it did is in the snapshots when its answer arrives)
/// and by the session thread when it fails; any thread reads the snapshots. They are built and stored under a lock,
/// so the last ones stored are the last ones built.
/// </para>
/// </summary>
internal sealed class StatusPublisher : IDisposable
{
    /// <summary>How often the snapshots are published.</summary>
    public static readonly TimeSpan Every = TimeSpan.FromMilliseconds(100);

    private readonly RobotSession _session;
    private readonly BusRobot _bus;
    private readonly SafetySupervisor _supervisor;
    private readonly string _transport;
    private readonly SessionEvents _events;
    private readonly RunLevelLog _runLevels;
    private readonly ModuleParameters _parameters;
    private readonly SessionModules _modules;
    private readonly SessionThreadState _sessionThread;
    private readonly RobotEventSubscription _robotEvents;
    private readonly Thread _thread;
    private readonly Lock _publishGate = new();
    private volatile SessionStatus _status;
    private volatile IReadOnlyList<ControllerView> _controllers;
    private CancellationToken _stop;

    /// <summary>Publishes the first snapshots; <see cref="Start"/> starts the thread.</summary>
    public StatusPublisher(RobotSession session, string transport, SessionEvents events, RunLevelLog runLevels, ModuleParameters parameters, SessionModules modules, SessionThreadState sessionThread, RobotEventSubscription robotEvents)
    {
        _session = session;
        _bus = session.Robot;
        _supervisor = session.Supervisor;
        _transport = transport;
        _events = events;
        _runLevels = runLevels;
        _parameters = parameters;
        _modules = modules;
        _sessionThread = sessionThread;
        _robotEvents = robotEvents;
        _runLevels.CatchUp();
        _status = BuildStatus();
        _controllers = BuildControllers();
        _thread = new Thread(PublishUntilStopped) { Name = "console session (status)", IsBackground = true };
    }

    /// <summary>The run status, as last published.</summary>
    public SessionStatus Status => _status;

    /// <summary>The bus page's modules and motors, as last published.</summary>
    public IReadOnlyList<ControllerView> Controllers => _controllers;

    /// <summary>True while the motors are driven (the robot layer is enabled): the status's torque, the commands' motors-on refusals.</summary>
    public static bool TorqueOn(BusRobot bus) => bus.State == Robot.States.RobotState.Enabled;

    /// <summary>Starts the status thread; it stops after one last turn once <paramref name="stop"/> is cancelled.</summary>
    public void Start(CancellationToken stop)
    {
        _stop = stop;
        _thread.Start();
    }

    /// <summary>Waits for the status thread's last turn.</summary>
    public void Join() => _thread.Join();

    /// <summary>
    /// After a command: copies the run levels into the event log and publishes the run status and the bus page's
    /// modules and motors now (the robot's events stay with the status thread, their one reader).
    /// </summary>
    public void PublishAfterCommand()
    {
        _runLevels.CatchUp();
        PublishSnapshots();
    }

    /// <summary>Publishes the run status now (the session thread, when it fails).</summary>
    public void PublishStatus()
    {
        lock (_publishGate)
        {
            _status = BuildStatus();
        }
    }

    /// <summary>The session's state while the robot node holds for a plug-in fault: which plug-in, and what it threw.</summary>
    private static string HeldBy(IReadOnlyList<Runtime.Graph.PluginFault> faults) =>
        faults.Count == 0 ? "holding (a plug-in faulted)" : $"holding: plug-in '{faults[0].Instance}' faulted ({faults[0].Message})";

    /// <summary>The run status as it is now.</summary>
    public SessionStatus BuildStatus()
    {
        var totals = _bus.Client.Totals(_bus.Controllers.Select(c => c.Id));
        var stats = _session.Loop.Statistics;
        var faults = _bus.Faults;
        var phase = _sessionThread.Phase;
        var state = phase == "running" && _session.Node.Holding ? HeldBy(_session.Graph.Program.Faults) : phase;
        var faultNames = Enum.GetValues<RobotFaults>().Where(f => f != RobotFaults.None && faults.HasFlag(f)).Select(f => f.ToString())
            .Concat(_supervisor.Level == RunLevel.EStop ? _supervisor.Trips.Select(t => $"trip: {t}") : []);
        return new SessionStatus(
            _session.Connection.Definition!.Name,
            Path.GetFileName(_session.Graph.Path),
            _transport,
            _bus.Controllers.Count,
            _modules.Found,
            _session.Graph.Document.LoopRateHz,
            _session.Loop.TickCount,
            stats.DeadlineMisses,
            stats.MedianUs,
            stats.P99Us,
            stats.MaxUs,
            _session.IsVirtual ? _sessionThread.TickAllocatedBytes : null,
            _events.Now,
            _supervisor.Level.Name(),
            _bus.State.ToString(),
            state,
            TorqueOn(_bus),
            [.. faultNames],
            _session.Graph.Program.FaultCount,
            new BusCounters(_bus.Cycles, totals.Frames, totals.CrcErrors, totals.Timeouts, totals.Retries));
    }

    /// <inheritdoc />
    public void Dispose() => _robotEvents.Dispose();

    /// <summary>Names of the set bits of <paramref name="bits"/>, as the control table names them.</summary>
    private static string[] Names(HardwareErrors bits) => bits.IsNone ? [] : bits.ToString().Split(", ");

    /// <summary>A module's last reset in words, its cause as the control table names it, and whether it was before the host connected.</summary>
    private static string ResetCause(RobotController c) =>
        c.LastResetCause == 0 ? "none reported"
        : (Bus.Protocol.ControlTable.Firmware.Codes("reset_cause").TryGetValue(c.LastResetCause, out var name) ? name : $"cause {c.LastResetCause}")
          + (c.LastResetBeforeConnect ? " (before the host connected)" : " (while connected)");

    private void PublishUntilStopped()
    {
        do
        {
            PublishOnce();
        }
        while (!_stop.WaitHandle.WaitOne(Every));

        PublishOnce();
    }

    private void PublishOnce()
    {
        while (_robotEvents.TryRead(out var e))
        {
            _events.Add("robot", e.Message);
        }

        _runLevels.CatchUp();
        _parameters.ReadNextWaiting();
        PublishSnapshots();
    }

    private void PublishSnapshots()
    {
        lock (_publishGate)
        {
            _status = BuildStatus();
            _controllers = BuildControllers();
        }
    }

    /// <summary>The bus page's modules and motors, as the robot core last found them.</summary>
    private List<ControllerView> BuildControllers()
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
                    return new ParameterSpec(p.Key, p.Label, p.Unit, _parameters.Value(c.Id, m.Config.Channel, p.Key), p.FileValue(m.Config), min, max);
                })],
                _bus.SentGoalRad(m) * 180 / Math.PI,
                _bus.LoopGoalRad(m) * 180 / Math.PI,
                m.SpeedLimitRadS * 180 / Math.PI,
                RingRecorder.DesiredSignal(m.Config.FullName),
                RingRecorder.MeasuredSignal(m.Config.FullName))).ToList();
            list.Add(new ControllerView(
                c.Id,
                _modules.NameOf(c),
                c.Present,
                c.MissedReplies,
                c.ModelNumber,
                c.FirmwareVersion,
                ResetCause(c),
                c.Resets,
                c.BusWatchdogMs switch { < 0 => "not read yet", 0 => "off", var ms => $"{ms} ms" } + (status.HasAny(HardwareErrors.BusWatchdog) ? ", TRIPPED" : status.HasAny(HardwareErrors.BusHold) ? ", HOLDING" : string.Empty),
                Names(status),
                motors));
        }

        return list;
    }
}
