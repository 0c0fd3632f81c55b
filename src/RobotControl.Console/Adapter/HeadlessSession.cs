using RobotControl.Modules;
using System.Diagnostics;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Host.Harness;
using RobotControl.Runtime.Loop;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.WebConsole.Session;
using RobotControl.WebConsole.Urdf;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console's session over today's building blocks: the graph file, a <see cref="BusRobot"/> on the virtual robot
/// (real firmware, paced to real time) or a real transport, and the <see cref="ControlLoop"/>. One thread owns the
/// bus: it runs the bus cycles, applies the console's queued commands between them, polls module status and publishes
/// snapshots. On the virtual robot the loop ticks on that thread from the virtual clock (as in the headless run); on a
/// real bus the loop runs on its own thread. The ring is fed by the loop's tick observer.
/// </summary>
public sealed partial class HeadlessSession : IConsoleSession
{
    private static readonly TimeSpan PublishEvery = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan PollEvery = TimeSpan.FromMilliseconds(200);

    private readonly HeadlessSessionOptions _options;
    private readonly TimeProvider _clock;
    private readonly LoadedGraph _loaded;
    private readonly RobotDefinition _robot;
    private readonly VirtualRobot? _sim;
    private readonly BusRobot _bus;
    private readonly ControlLoop _loop;
    private readonly RingRecorder _recorder;
    private readonly CommandQueue _commands = new();
    private readonly Session.EventLog _events = new();
    private readonly Dictionary<int, string> _names = [];
    private readonly Dictionary<int, ModuleStatus> _status = [];
    private readonly Dictionary<(int Module, int Channel, string Key), double> _parameters = [];
    private readonly TickStatistics _busTiming = new();
    private readonly TickStatistics _pollTiming = new();
    private readonly TickStatistics _commandTiming = new();
    private readonly Thread _thread;
    private readonly long _begin;
    private volatile bool _stop;
    private volatile bool _torqueOn;
    private volatile SessionStatus _statusView;
    private volatile IReadOnlyList<ControllerView> _controllersView = [];
    private volatile string _state = "starting";
    private int _found;

    /// <summary>Loads the graph, opens the robot, discovers its modules, turns the motors on and starts the session thread.</summary>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">The graph names no robot, or the transport does not fit.</exception>
    /// <exception cref="IOException">The transport cannot be opened.</exception>
    public HeadlessSession(HeadlessSessionOptions options, IUrdfSource? urdf = null)
    {
        ArgumentNullException.ThrowIfNull(options);
        _options = options;
        _clock = options.Virtual ? new ManualTimeProvider() : TimeProvider.System;
        _loaded = GraphFile.Load(options.GraphPath, options.Catalog, _clock);
        _robot = _loaded.Robot ?? throw new InvalidOperationException($"{_loaded.Path}: the graph names no robot file");
        Transport = options.Virtual ? $"virtual:{Path.GetFileName(_robot.SourceFile)}" : options.Transport ?? _loaded.Document.Transport;
        IByteLink link;
        if (options.Virtual)
        {
            _sim = new VirtualRobot(_robot, (ManualTimeProvider)_clock, new VirtualRobotOptions { InitialJointsRad = HeadlessRun.InitialCommand(_loaded), Seed = options.Seed });
            link = _sim.OpenLink();
        }
        else
        {
            if (Transport.StartsWith("virtual", StringComparison.OrdinalIgnoreCase))
            {
                throw new InvalidOperationException($"the graph's transport is '{Transport}': use --virtual, or name a serial, usb or tcp transport with --transport");
            }

            link = LinkFactory.Open(Transport);
        }

        _bus = new BusRobot(_robot, new BusClient(link, _clock));
        _begin = _clock.GetTimestamp();
        _recorder = new RingRecorder(_loaded.Program, _loaded.RobotNode!, options.RingCapacity);
        Model = BuildModel(urdf ?? new DhUrdfSource());
        RunDiscovery();
        _bus.EnableTorque(true);
        _torqueOn = true;
        _loaded.RobotNode!.Attach(_bus);
        _loop = new ControlLoop(_loaded.Program, _clock, _loaded.Document.LoopRateHz, _recorder);
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
        Timing($"control loop tick ({_loaded.Program.Order.Count} instances)", _loop.Statistics),
        Timing("bus cycle (sync write + sync read)", _busTiming),
        Timing("module status poll", _pollTiming),
        Timing("console commands", _commandTiming),
    ];

    /// <summary>The loop (benchmarks read its statistics).</summary>
    internal ControlLoop Loop => _loop;

    /// <inheritdoc />
    public IReadOnlyList<EventEntry> EventsAfter(long after) => _events.After(after);

    /// <inheritdoc />
    public void Dispose()
    {
        _stop = true;
        _thread.Join();
        _commands.Close();
        _loop.Stop();
        try
        {
            _bus.EnableTorque(false);
        }
        catch (IOException)
        {
            // The bus is gone; nothing more to switch off.
        }

        _bus.Dispose();
        _sim?.Dispose();
    }

    private static ComponentTiming Timing(string name, TickStatistics s) => new(name, s.Count, s.MedianUs, s.P99Us, s.MaxUs);

    private double Now => _clock.GetElapsedTime(_begin).TotalSeconds;

    private void Run()
    {
        try
        {
            _state = "running";
            if (_sim is not null)
            {
                RunVirtual();
            }
            else
            {
                RunRealTime();
            }

            _state = "stopped";
        }
#pragma warning disable CA1031 // the session thread reports what ended it in the status and the event log
        catch (Exception ex)
#pragma warning restore CA1031
        {
            _state = "failed";
            _events.Add(Now, "session", $"the session thread stopped: {ex.Message}");
            _statusView = BuildStatus();
        }
    }

    private void RunVirtual()
    {
        // The loop ticks from a timer on the virtual clock while the bus cycles move it; the thread sleeps whenever
        // the virtual clock gets ahead of the wall clock, so the virtual robot runs in real time.
        var wall = Stopwatch.StartNew();
        using var timer = _clock.CreateTimer(_ => _loop.Step(), null, _loop.Period, _loop.Period);
        var nextPublish = 0.0;
        var nextPoll = 0.0;
        while (!_stop)
        {
            Between(ref nextPublish, ref nextPoll);
            var begin = Stopwatch.GetTimestamp();
            _bus.RunFor(TimeSpan.FromMilliseconds(1));
            _busTiming.Record(Stopwatch.GetTimestamp() - begin);
            var ahead = Now - wall.Elapsed.TotalSeconds;
            if (ahead > 0.002)
            {
                Thread.Sleep(TimeSpan.FromSeconds(ahead));
            }
        }
    }

    private void RunRealTime()
    {
        _loop.Start();
        var nextPublish = 0.0;
        var nextPoll = 0.0;
        try
        {
            while (!_stop && _loop.ThreadFailure is null)
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
                while (Stopwatch.GetElapsedTime(begin) < TimeSpan.FromMilliseconds(1) && !_stop)
                {
                    Thread.SpinWait(50);
                }
            }
        }
        finally
        {
            _loop.Stop();
        }

        if (_loop.ThreadFailure is { } failure)
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

        var now = Now;
        if (now >= nextPoll)
        {
            nextPoll = now + PollEvery.TotalSeconds;
            begin = Stopwatch.GetTimestamp();
            PollModules();
            _pollTiming.Record(Stopwatch.GetTimestamp() - begin);
        }

        if (now >= nextPublish)
        {
            nextPublish = now + PublishEvery.TotalSeconds;
            _statusView = BuildStatus();
            PublishControllers();
        }
    }

    /// <summary>Discovers the modules, logs and returns what was found, and reads the present ones' parameters.</summary>
    private List<string> RunDiscovery()
    {
        var report = _bus.Discover();
        _found = report.Present.Count;
        var lines = report.Lines().Select(l => l.Trim()).ToList();
        foreach (var line in lines)
        {
            _events.Add(Now, "discovery", line);
        }

        foreach (var c in _bus.Controllers.Where(c => c.Present))
        {
            ReadParameters(c);
        }

        while (_bus.Events.TryDequeue(out _))
        {
            // Discovery's findings are logged above, from the report.
        }

        return lines;
    }

    private void ReadParameters(RobotController c)
    {
        foreach (var m in c.Motors)
        {
            foreach (var p in MotorParameter.All)
            {
                _parameters[(c.Id, m.Config.Channel, p.Key)] = p.FromCounts(m.Config, _bus.ReadParameter(c.Id, p.Field.Name, m.Config.Channel));
            }
        }
    }

    private void PollModules()
    {
        foreach (var c in _bus.Controllers)
        {
            if (!c.Present)
            {
                continue;
            }

            try
            {
                _status[c.Id] = ModuleStatus.Read(_bus, c);
            }
            catch (IOException)
            {
                // A module that stops answering is reported by the bus cycles; keep its last status.
            }
        }
    }

    private SessionStatus BuildStatus()
    {
        long frames = 0, crc = 0, timeouts = 0, retries = 0;
        foreach (var c in _bus.Controllers)
        {
            var s = _bus.Client.Statistics(c.Id);
            frames += s.FramesSent + s.FramesReceived;
            crc += s.CrcErrors;
            timeouts += s.Timeouts;
            retries += s.Retries;
        }

        var stats = _loop?.Statistics;
        var faults = _bus.Faults;
        var state = _state == "running" && _loaded.RobotNode!.Holding ? "holding (a plug-in faulted)" : _state;
        return new SessionStatus(
            _robot.Name,
            Path.GetFileName(_loaded.Path),
            Transport,
            _bus.Controllers.Count,
            _found,
            _loaded.Document.LoopRateHz,
            _loop?.TickCount ?? 0,
            stats?.DeadlineMisses ?? 0,
            stats?.MedianUs ?? 0,
            stats?.P99Us ?? 0,
            stats?.MaxUs ?? 0,
            Now,
            state,
            _torqueOn,
            faults == RobotFaults.None ? [] : [.. Enum.GetValues<RobotFaults>().Where(f => f != RobotFaults.None && faults.HasFlag(f)).Select(f => f.ToString())],
            _loaded.Program.FaultCount,
            new BusCounters(_bus.Cycles, frames, crc, timeouts, retries));
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
                    var (min, max) = p.Encodable(m.Config);
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

    private RobotModelView BuildModel(IUrdfSource source)
    {
        var urdf = source.For(_robot);
        var normal = _robot.MirrorPlaneNormal;
        var arms = _robot.Arms.Select(a => new ArmView(
            a.Name,
            [a.BaseOffsetMm.X / 1000, a.BaseOffsetMm.Y / 1000, a.BaseOffsetMm.Z / 1000],
            a.Mirrored ? [normal.X, normal.Y, normal.Z] : null,
            [.. _robot.Joints.Select(j => RingRecorder.PositionSignal(a.Name, j.Name))],
            [.. _robot.Joints.Select(j => RingRecorder.CommandSignal(a.Name, j.Name))])).ToList();
        return new RobotModelView(urdf.Xml, urdf.JointNames, arms);
    }
}
