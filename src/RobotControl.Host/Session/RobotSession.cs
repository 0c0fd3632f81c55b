using RobotControl.Bus.Transports;
using RobotControl.Host.Realtime;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;

namespace RobotControl.Host.Session;

/// <summary>
/// The one place a robot session is brought up and down: graph file -> robot file -> transport (virtual, serial,
/// USB, TCP) -> robot (discovered, motors on) -> graph attached to it -> control loop. Then either
/// <see cref="RunVirtual"/> (a deterministic <see cref="VirtualSchedule"/> on the virtual clock) or
/// <see cref="StartRealtime"/> / <see cref="Stop"/> (bus and loop on threads of their own, on the wall clock).
/// Used by <c>robotctl run</c>, <c>bench loop</c> and, through <see cref="RobotConnection"/>, the bus commands.
/// </summary>
public sealed class RobotSession : IDisposable
{
    private readonly ManualTimeProvider? _loopClock;
    /// <summary>How long the bus cycle runs, motors off, before the watchdogs are armed.</summary>
    public static readonly TimeSpan WarmUp = TimeSpan.FromMilliseconds(300);

    private bool _running;
    private StopCheck? _stopped;
    private long _stopRequestedAt;
    private CpuLatencyHold? _cpuLatency;

    private RobotSession(LoadedGraph graph, RobotConnection connection, ManualTimeProvider? loopClock, DiscoveryReport discovery, ControlLoop loop, SafetySupervisor supervisor)
    {
        Supervisor = supervisor;
        Graph = graph;
        Connection = connection;
        _loopClock = loopClock;
        Discovery = discovery;
        Loop = loop;
    }

    /// <summary>The graph file, loaded.</summary>
    public LoadedGraph Graph { get; }

    /// <summary>The robot's bus.</summary>
    public RobotConnection Connection { get; }

    /// <summary>The robot layer.</summary>
    public BusRobot Robot => Connection.Robot!;

    /// <summary>The safety supervisor: run level, per-cycle checks, trips.</summary>
    public SafetySupervisor Supervisor { get; }

    /// <summary>The robot node of the graph (attached to <see cref="Robot"/>).</summary>
    public RobotNode Node => Graph.RobotNode!;

    /// <summary>The virtual robot (null on a real bus).</summary>
    public VirtualRobot? Simulation => Connection.Simulation;

    /// <summary>What discovery found when the session opened.</summary>
    public DiscoveryReport Discovery { get; }

    /// <summary>The control loop.</summary>
    public ControlLoop Loop { get; }

    /// <summary>The bus's clock (simulated or the system's): run time is measured on it.</summary>
    public TimeProvider Clock => Connection.Clock;

    /// <summary>True for a virtual session.</summary>
    public bool IsVirtual => Simulation is not null;

    /// <summary>
    /// Brings a session up: loads the graph, opens its robot, discovers the modules, puts a safety supervisor on it
    /// (run level INIT), homes it (HOMING) and turns the motors on holding position (PEDAL_UP), attaches the graph and
    /// builds the loop. Teleoperation drives the arms only after <see cref="SafetySupervisor.PedalDown"/>.
    /// </summary>
    /// <exception cref="Runtime.Graph.GraphException">The graph file is invalid.</exception>
    /// <exception cref="InvalidOperationException">The graph names no robot, or a real session names a virtual transport.</exception>
    /// <exception cref="IOException">The transport cannot be opened or a module refuses.</exception>
    public static RobotSession Open(SessionOptions options, PluginCatalog catalog)
    {
        ArgumentNullException.ThrowIfNull(options);
        ArgumentNullException.ThrowIfNull(catalog);
        var loopClock = options.Virtual ? new ManualTimeProvider() : null;
        var loaded = GraphFile.Load(options.GraphPath, catalog, loopClock ?? TimeProvider.System, options.SettingOverrides);
        var robot = loaded.Robot ?? throw new InvalidOperationException($"{loaded.Path}: the graph names no robot file");
        RobotConnection connection;
        if (options.Virtual)
        {
            connection = RobotConnection.OpenVirtual(robot, new VirtualRobotOptions { InitialJointsRad = InitialCommand(loaded), Seed = options.Seed }, null, options.WrapLink, options.Robot);
        }
        else
        {
            var transport = options.Transport ?? loaded.Document.Transport;
            if (transport.StartsWith("virtual", StringComparison.OrdinalIgnoreCase))
            {
                throw new InvalidOperationException($"the graph's transport is '{transport}': run it with --virtual, or name a serial, usb or tcp transport");
            }

            var link = LinkFactory.Open(transport);
            connection = RobotConnection.OpenReal(options.WrapLink?.Invoke(link, TimeProvider.System) ?? link, robot, null, options.Robot);
        }

        try
        {
            var bus = connection.Robot!;
            var discovery = bus.Discover();
            var supervisor = new SafetySupervisor(bus, robot.Safety, TimeSpan.FromSeconds(1.0 / loaded.Document.LoopRateHz));
            if (options.Virtual)
            {
                supervisor.Home("session"); // a real session homes and arms the modules in StartRealtime, once the cycle runs at rate
            }

            loaded.RobotNode!.Attach(bus, supervisor); // the graph reports the operator's pedals and input ages to the supervisor
            supervisor.WatchGraph(loaded.Program, loaded.RobotNode!); // a late loop names its plug-in; a plug-in fault upstream trips
            var observer = options.Observer?.Invoke(loaded.RobotNode!, bus);
            var loop = new ControlLoop(loaded.Program, loopClock ?? TimeProvider.System, loaded.Document.LoopRateHz, observer);
            return new RobotSession(loaded, connection, loopClock, discovery, loop, supervisor);
        }
        catch
        {
            connection.Dispose();
            throw;
        }
    }

    /// <summary>Joint angles per arm that the graph will command first (the initial values on the wires into the robot node).</summary>
    public static IReadOnlyList<double[]> InitialCommand(LoadedGraph loaded)
    {
        ArgumentNullException.ThrowIfNull(loaded);
        var robot = loaded.Robot ?? throw new InvalidOperationException("the graph names no robot");
        var outputs = loaded.Program.OutputSignals;
        var result = new List<double[]>();
        foreach (var arm in robot.Arms)
        {
            var q = robot.Joints.Select(j => j.MidRad).ToArray();
            for (var j = 0; j < q.Length; j++)
            {
                var wire = loaded.Document.Wires.FirstOrDefault(w => w.To == $"{RobotNode.InstanceName}.{arm.Name}.{robot.Joints[j].Name}");
                if (wire is not null)
                {
                    var index = IndexOf(outputs.Names, wire.From);
                    q[j] = Math.Clamp(outputs.Values[index], robot.Joints[j].MinRad, robot.Joints[j].MaxRad);
                }
            }

            result.Add(q);
        }

        return result;
    }

    /// <summary>
    /// Runs <paramref name="ticks"/> loop ticks on the virtual schedule (as fast as the machine goes, deterministic);
    /// <paramref name="afterCycle"/> runs after each bus cycle, <paramref name="aroundTick"/> (if given) runs each tick.
    /// </summary>
    /// <exception cref="InvalidOperationException">The session is not virtual, or already running.</exception>
    /// <param name="ticks">Ticks to run.</param>
    /// <param name="afterCycle">Runs after each bus cycle (progress, events).</param>
    /// <param name="aroundTick">Runs each tick instead of <see cref="ControlLoop.Step"/>.</param>
    /// <param name="stopWhen">Checked after each bus cycle: true ends the run early (a stop request, a robot fault).</param>
    /// <param name="tickCost">Whether a tick's CPU time counts against its period (<see cref="VirtualSchedule"/>).</param>
    public void RunVirtual(long ticks, Action? afterCycle = null, Action<ControlLoop, long>? aroundTick = null, Func<bool>? stopWhen = null, VirtualTickCost tickCost = VirtualTickCost.Measured)
    {
        if (_loopClock is null || Connection.VirtualClock is null)
        {
            throw new InvalidOperationException("RunVirtual needs a virtual session (SessionOptions.Virtual)");
        }

        new VirtualSchedule(Robot, Connection.VirtualClock, _loopClock, Loop, ticks, aroundTick, tickCost).Run(afterCycle, stopWhen);
        Loop.Stop();
    }

    /// <summary>
    /// Starts the bus thread and the loop thread (real bus, wall clock). The motors are still off: the code of the
    /// graph and the cycle is compiled first (<see cref="PrepareRealtime"/>), then the bus cycle is run for
    /// <see cref="WarmUp"/> on this thread, and the stop's torque-off and read-back once (every path JIT-compiled,
    /// buffers touched), so that the modules' bus watchdogs are armed only when the cycle runs at rate; then the motors
    /// go on (watchdogs armed) and the threads start straight away, with <paramref name="threads"/>' scheduling
    /// (priority, CPUs).
    /// </summary>
    /// <exception cref="InvalidOperationException">The session is virtual, or already running.</exception>
    /// <exception cref="IOException">A module refuses torque (e.g. a latched watchdog error).</exception>
    public void StartRealtime(RealtimeThreads? threads = null)
    {
        if (IsVirtual || _running)
        {
            throw new InvalidOperationException(IsVirtual ? "a virtual session runs on its schedule (RunVirtual)" : "the session is running already");
        }

        var scheduling = threads ?? RealtimeThreads.Default;
        PrepareRealtime(scheduling);
        Robot.RunFor(WarmUp);
        _ = StopCheck.TorqueOffAndVerify(Robot); // the stop's path too: compiled now, it cannot stall a stop past the watchdog
        Supervisor.Home("session"); // INIT -> HOMING -> PEDAL_UP: motors on, watchdogs armed
        StartThreads(scheduling);
    }

    /// <summary>
    /// Starts the bus thread and the loop thread with the motors as they are (the console on a real bus: the operator
    /// turns them on); the code is compiled first (<see cref="PrepareRealtime"/>). From here on, set-up and commands
    /// run on the bus thread between cycles.
    /// </summary>
    /// <exception cref="InvalidOperationException">The session is virtual, or already running.</exception>
    public void StartBus(RealtimeThreads threads)
    {
        ArgumentNullException.ThrowIfNull(threads);
        if (IsVirtual || _running)
        {
            throw new InvalidOperationException(IsVirtual ? "a virtual session runs on its schedule (RunVirtual)" : "the session is running already");
        }

        PrepareRealtime(threads);
        StartThreads(threads);
    }

    private void StartThreads(RealtimeThreads scheduling)
    {
        _running = true;
        scheduling.Start(Robot.Start, Loop.Start); // each thread schedules itself (.NET threads do not inherit it)
    }

    /// <summary>
    /// What every wall-clock run does before its threads start: compiles the graph's and the cycle's code
    /// (<see cref="CodeWarmUp"/>), so that the loop's first ticks do not wait for the JIT, and, when
    /// <paramref name="threads"/> ask for it, holds the CPUs' wake-up latency at 0 us until <see cref="Stop"/>.
    /// <see cref="StartRealtime"/> calls it before arming; a caller that runs the bus cycle on its own thread (the
    /// console) calls it before starting its threads.
    /// </summary>
    public void PrepareRealtime(RealtimeThreads threads)
    {
        ArgumentNullException.ThrowIfNull(threads);
        _ = CodeWarmUp.Prepare(CodeWarmUp.CycleTypes(Graph.Program));
        _cpuLatency?.Dispose();
        _cpuLatency = threads.HoldCpuLatency ? CpuLatencyHold.Request() : null; // until the stop: idle CPUs wake at once
    }

    /// <summary>Whether the CPUs' wake-up latency is held for the run (<see cref="CpuLatencyHold"/>), in one line; null before <see cref="PrepareRealtime"/> or when not asked for.</summary>
    public string? CpuLatency => _cpuLatency?.Outcome;

    /// <summary>
    /// The first thing any stop does (a signal, the console closing, <see cref="Stop"/>), from any thread, lock-free and
    /// never waiting: the next write of the bus cycle switches the motors off, ahead of any queued work, whose running
    /// piece is cut short at its next transaction. <see cref="Stop"/> then reads them back. The first call's time is
    /// kept (<see cref="StopRequestedAt"/>).
    /// </summary>
    public void StopMotorsNow(string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        MarkStopRequested();
        Robot.EmergencyHold(reason, torqueOff: true);
    }

    /// <summary>Keeps the time of the first stop request (any thread; later ones change nothing).</summary>
    private void MarkStopRequested() => _ = Interlocked.CompareExchange(ref _stopRequestedAt, Clock.GetTimestamp(), 0);

    /// <summary>When the first stop was asked for, on <see cref="Clock"/> (0: not yet).</summary>
    public long StopRequestedAt => Interlocked.Read(ref _stopRequestedAt);

    /// <summary>How long a stop waits for the loop's tick to end, once the motors are off and read back.</summary>
    public static readonly TimeSpan LoopStopWait = TimeSpan.FromSeconds(1);

    /// <summary>
    /// Stops the session, the motors first: they are asked off (<see cref="StopMotorsNow"/>), the bus thread ends
    /// after its cycle, the motors are switched off on every module and read back (<see cref="StopCheck"/>); only then
    /// is the loop stopped, waiting at most <see cref="LoopStopWait"/> for a tick that does not end (a hung plug-in
    /// cannot hold a stop: <see cref="StopCheck.LoopHung"/> names it). The first call does it, later calls return its result.
    /// </summary>
    public StopCheck Stop()
    {
        if (_stopped is not null)
        {
            return _stopped;
        }

        if (_running)
        {
            _running = false;
            StopMotorsNow("session stop: motors off");
            Robot.Stop();
        }
        else
        {
            MarkStopRequested(); // nothing cycles: the read-back below switches the motors off itself
        }

        var check = StopCheck.TorqueOffAndVerify(Robot) with { AfterRequest = Clock.GetElapsedTime(StopRequestedAt) };
        string? hung = null;
        if (!Loop.Stop(LoopStopWait))
        {
            hung = Graph.Program.Profile.InTick() is { } t
                ? string.Create(System.Globalization.CultureInfo.InvariantCulture, $"the control loop did not end: {t.Name} for {t.Ms / 1e3:0.0} s; its plug-ins were not stopped")
                : "the control loop did not end; its plug-ins were not stopped";
        }

        _cpuLatency?.Dispose();
        return _stopped = check with { LoopHung = hung };
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _ = Stop();
        if (_stopped?.LoopHung is null)
        {
            Loop.Dispose();
        }

        Connection.Dispose();
    }

    private static int IndexOf(IReadOnlyList<string> names, string name)
    {
        for (var i = 0; i < names.Count; i++)
        {
            if (names[i] == name)
            {
                return i;
            }
        }

        return -1;
    }
}
