using System.Diagnostics;
using RobotControl.Host.Recording;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Kinematics.Urdf;
using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Loop;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console's live session on a robot: a <see cref="RobotSession"/> (graph, robot, bus, safety supervisor, control
/// loop, brought up by the session layer) run on the robot's one bus cycle. On the virtual robot the session layer's
/// <see cref="VirtualSchedule"/> runs the cycles and ticks the loop on the session thread, paced to the wall clock; on a
/// real bus the session layer's bus thread and loop thread run them (<see cref="RobotSession.StartBus"/>). The console's
/// commands run in the robot's slot between cycles (<see cref="CommandQueue"/>); an emergency stop goes to the
/// supervisor directly. It has no bus client of its own: what it shows of the modules is what the robot core found
/// (status, resets, watchdog, torque read back, motor errors), published with the run status every 100 ms by a
/// thread of its own (<see cref="StatusPublisher"/>). The ring is fed by the loop's tick observer.
/// <para>
/// This type is the session's life: it opens the session, runs the session thread and closes it with the stop's
/// report; the state it owns (the session thread, the end) is written by the session thread and by
/// <see cref="Close"/> under a lock. Each other part owns its own state: <see cref="SessionEvents"/>,
/// <see cref="RunLevelLog"/>, <see cref="SessionModules"/>, <see cref="ModuleParameters"/>,
/// <see cref="SessionThreadState"/>, <see cref="StatusPublisher"/>, <see cref="SurgeonStation"/>; the commands
/// (<see cref="ModuleCommands"/>, <see cref="MotorCommands"/>, <see cref="RunLevelCommands"/>) own none.
/// </para>
/// </summary>
public sealed class LiveSession : IConsoleSession
{
    /// <summary>Cycles between two reads of one module's torque and motor errors (the modules in turn).</summary>
    private const int DetailPollCycles = 50;

    private readonly RobotSession _session;
    private readonly RingRecorder _recorder;
    private readonly CommandQueue _queue;
    private readonly SessionEvents _events;
    private readonly SessionThreadState _sessionThread = new();
    private readonly StatusPublisher _publisher;
    private readonly ConsoleRecording _mcap;
    private readonly ModuleCommands _modules;
    private readonly MotorCommands _motors;
    private readonly RunLevelCommands _runLevel;
    private readonly SurgeonStation _surgeon;
    private readonly CancellationTokenSource _stop = new();
    private readonly Lock _closeLock = new();
    private readonly Host.Realtime.RealtimeThreads _threads;
    private readonly Thread _thread;
    private readonly ManualResetEventSlim _ownsBus = new();
    private SessionEnd? _end;

    /// <summary>
    /// Brings the session up through the session layer (graph, robot, discovery, safety supervisor homing to
    /// PEDAL_UP with the motors on, control loop), queues the modules' parameter reads and starts the session thread
    /// and the status thread.
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
            new SessionOptions { GraphPath = options.GraphPath, Virtual = options.Virtual, Seed = options.Seed, Transport = options.Transport, WrapLink = options.WrapLink, Observer = (_, _) => slot, Robot = new BusRobotOptions { DetailPollCycles = DetailPollCycles } },
            options.Catalog);
        var robot = _session.Connection.Definition!;
        var bus = _session.Robot;
        _events = new SessionEvents(_session.Clock);
        _queue = new CommandQueue(bus.Slot);
        var robotEvents = bus.Events.Subscribe();
        try
        {
            faults.Schedule(_session.Simulation, robot);
        }
        catch (FormatException)
        {
            _session.Dispose();
            throw;
        }
        _recorder = new RingRecorder(_session.Graph.Program, _session.Node, _session.Robot, options.RingCapacity);
        var tap = new RecordingTap(_session.Node, _session.Robot, _recorder); // the MCAP recording's side on the loop thread, then the plots' ring
        slot.Target = tap;
        _mcap = new ConsoleRecording(_session, tap, _events, options.Record, options.RecordFolder);
        try
        {
            _mcap.StartFirst();
        }
        catch (IOException)
        {
            _session.Dispose();
            throw;
        }

        Transport = options.Virtual ? $"virtual:{Path.GetFileName(robot.SourceFile)}" : options.Transport ?? _session.Graph.Document.Transport;
        Model = BuildModel(robot);
        var modules = new SessionModules(_events);
        var parameters = new ModuleParameters(bus, _queue, _events);
        var runLevels = new RunLevelLog(_session.Supervisor, _events);
        modules.Record(_session.Discovery);
        parameters.QueuePresentModules(); // read between the first cycles, one module at a time
        var checks = new CommandChecks(bus, _session.Supervisor);
        _publisher = new StatusPublisher(_session, Transport, _events, runLevels, parameters, modules, _sessionThread, robotEvents);
        _modules = new ModuleCommands(bus, _queue, _events, checks, modules, parameters);
        _motors = new MotorCommands(_session, _queue, _events, checks);
        _runLevel = new RunLevelCommands(_session.Supervisor, bus, _queue, _events, runLevels, _sessionThread);
        _surgeon = new SurgeonStation(_session, _queue, _events);
        _thread = new Thread(Run) { Name = "console session (bus)", IsBackground = true, Priority = ThreadPriority.AboveNormal };
        _thread.Start();
        _ownsBus.Wait(); // from here on a command runs between cycles on the bus's owner, never on the caller's thread
        _publisher.Start(_stop.Token);
    }

    /// <summary>The transport in use.</summary>
    public string Transport { get; }

    /// <inheritdoc />
    public SessionStatus Status => _publisher.Status;

    /// <inheritdoc />
    public string? RecordingFile => _mcap.File;

    /// <inheritdoc />
    public void NoteCommand(string who, string what) => _mcap.Note(who, what);

    /// <inheritdoc />
    public Task<CommandResult> RecordAsync(bool on) => Task.Run(() => _mcap.Record(on)); // file I/O off the caller's thread

    /// <inheritdoc />
    public IReadOnlyList<ControllerView> Controllers => _publisher.Controllers;

    /// <inheritdoc />
    public SignalRing Signals => _recorder.Ring;

    /// <inheritdoc />
    public RobotModelView Model { get; }

    /// <inheritdoc />
    public IReadOnlyList<ComponentTiming> Timings =>
    [
        Timing($"control loop tick ({_session.Graph.Program.Order.Count} instances)", _session.Loop.Statistics),
        Timing(_session.IsVirtual ? "bus cycle (write, read, publish, check, between cycles)" : "bus cycle (timed on the virtual robot only)", _sessionThread.BusCycle),
    ];

    /// <inheritdoc />
    public SurgeonView Surgeon => _surgeon.View;

    /// <inheritdoc />
    public WorkspaceView Workspace => _surgeon.Workspace;

    /// <summary>The loop (benchmarks read its statistics).</summary>
    internal ControlLoop Loop => _session.Loop;

    /// <inheritdoc />
    public IReadOnlyList<EventEntry> EventsAfter(long after) => _events.After(after);

    /// <inheritdoc />
    public Task<CommandResult> DiscoverAsync() => Answered(_modules.DiscoverAsync());

    /// <inheritdoc />
    public Task<CommandResult> RenameAsync(int controllerId, string name) => Answered(_modules.RenameAsync(controllerId, name));

    /// <inheritdoc />
    public Task<CommandResult> ReloadParametersAsync(int controllerId) => Answered(_modules.ReloadParametersAsync(controllerId));

    /// <inheritdoc />
    public Task<CommandResult> RebootAsync(int controllerId) => Answered(_modules.RebootAsync(controllerId));

    /// <inheritdoc />
    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value) => Answered(_modules.WriteParameterAsync(motor, parameter, value));

    /// <inheritdoc />
    public Task<CommandResult> JogAsync(string motor, double degPerS) => Answered(_motors.JogAsync(motor, degPerS));

    /// <inheritdoc />
    public Task<CommandResult> SetpointAsync(string motor, double deg) => Answered(_motors.SetpointAsync(motor, deg));

    /// <inheritdoc />
    public Task<CommandResult> ReleaseAsync(string motor) => Answered(_motors.ReleaseAsync(motor));

    /// <inheritdoc />
    public Task<CommandResult> HomeAsync(string? motor) => Answered(_motors.HomeAsync(motor));

    /// <inheritdoc />
    public Task<CommandResult> TorqueAsync(bool on) => Answered(_runLevel.TorqueAsync(on));

    /// <inheritdoc />
    public Task<CommandResult> PedalAsync(bool down) => Answered(_runLevel.PedalAsync(down));

    /// <inheritdoc />
    /// <remarks>
    /// Answered as soon as the run level is E_STOP (the stop applied), not after the snapshots: their publication is
    /// started then and runs beside the answer, so a loaded publisher never holds the confirmation back.
    /// </remarks>
    public Task<CommandResult> EmergencyStopAsync() => AnsweredBeforePublishing(_runLevel.EmergencyStopAsync());

    /// <inheritdoc />
    public Task<CommandResult> ClearFaultsAsync() => Answered(_runLevel.ClearFaultsAsync());

    /// <inheritdoc />
    public Task<CommandResult> SetScaleAsync(string arm, double ratio) => Answered(_surgeon.SetScaleAsync(arm, ratio));

    /// <inheritdoc />
    public void StopMotorsNow(string reason) => _session.StopMotorsNow(reason);

    /// <inheritdoc />
    public SessionEnd Close()
    {
        lock (_closeLock)
        {
            if (_end is not null)
            {
                return _end;
            }

            StopMotorsNow("console closing: motors off"); // first, lock-free: the next write, ahead of queued commands
            _queue.Close();
            _stop.Cancel();
            _thread.Join();
            var stop = _session.Stop(); // loop and bus thread off, motors off through the robot's state machine (or written off directly), every module read back
            _mcap.Stop(); // after the motors are off and read back; the event log says what was written

            _publisher.Join();
            var last = _publisher.BuildStatus();
            _events.Add("session", $"stopped: {stop.Summary}");
            _end = new SessionEnd(last with { Session = "stopped", TorqueOn = stop.TorqueOn.Count > 0 }, stop, _events.After(0), Timings);
            return _end;
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _ = Close();
        _publisher.Dispose();
        _session.Dispose();
        _stop.Dispose();
        _ownsBus.Dispose();
    }

    /// <summary>The virtual robot's own output angle of <paramref name="motor"/> in degrees (tests: the simulation's truth), read on the session thread.</summary>
    internal Task<double> VirtualOutputDeg(string motor) => _motors.VirtualOutputDeg(motor);

    /// <summary>The safety supervisor's run level now (not the published status's, which may be up to <see cref="StatusPublisher.Every"/> old): what the tests time E-STOP by key against.</summary>
    internal string RunLevelNow => _session.Supervisor.Level.Name();

    private static ComponentTiming Timing(string name, TickStatistics s) => new(name, s.Count, s.MedianUs, s.P99Us, s.MaxUs);

    /// <summary>
    /// A command's answer, given once the run levels are in the event log and the snapshots (status, bus page) have been
    /// published again after it ran, so that what it did shows in <see cref="EventsAfter"/>, <see cref="Status"/> and
    /// <see cref="Controllers"/> when the caller has the answer. The publication runs on the thread pool, never on the
    /// bus's owner; once the session is stopping, the status thread's last turn and the stop's report are the last
    /// snapshots.
    /// </summary>
    private Task<CommandResult> Answered(Task<CommandResult> command) => command.ContinueWith(
        t =>
        {
            if (!_stop.IsCancellationRequested)
            {
                _publisher.PublishAfterCommand();
            }

            return t.GetAwaiter().GetResult();
        },
        CancellationToken.None,
        TaskContinuationOptions.None,
        TaskScheduler.Default);

    /// <summary>
    /// A command's answer as soon as it completed; the snapshots' publication (as in <see cref="Answered"/>) is started
    /// then on the thread pool and not waited for. The E-STOP's: its answer says the stop is applied, which the
    /// snapshots do not change.
    /// </summary>
    private Task<CommandResult> AnsweredBeforePublishing(Task<CommandResult> command) => command.ContinueWith(
        t =>
        {
            if (!_stop.IsCancellationRequested)
            {
                _ = Task.Run(_publisher.PublishAfterCommand, CancellationToken.None);
            }

            return t.GetAwaiter().GetResult();
        },
        CancellationToken.None,
        TaskContinuationOptions.ExecuteSynchronously,
        TaskScheduler.Default);

    /// <summary>The 3D view's model: the host's URDF of the robot (both arms) and each arm's joints and signals.</summary>
    private static RobotModelView BuildModel(Definitions.Model.RobotDefinition robot)
    {
        var urdf = UrdfExport.ToDocument(robot).ToString();
        var arms = robot.Arms.Select(a => new ArmView(
            a.Name,
            [.. robot.Joints.Select(j => UrdfExport.JointName(a.Name, j.Name))],
            [.. robot.Joints.Select(j => RingRecorder.PositionSignal(a.Name, j.Name))],
            [.. robot.Joints.Select(j => RingRecorder.CommandSignal(a.Name, j.Name))])).ToList();
        return new RobotModelView(urdf, arms);
    }

    /// <summary>The session thread: runs the bus cycles (virtual robot) or watches the loop (real bus) until the stop.</summary>
    private void Run()
    {
        try
        {
            _sessionThread.Phase = "running";
            if (_session.IsVirtual)
            {
                using var owns = _session.Robot.OwnBus(); // the schedule's thread owns the bus before the constructor returns
                _ownsBus.Set();
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
            _sessionThread.Phase = "failed";
            _events.Add("session", $"the session thread stopped: {ex.Message}");
            _publisher.PublishStatus();
            return;
        }
        finally
        {
            _ownsBus.Set(); // a session that failed before it ran no longer holds its constructor
        }

        _sessionThread.Phase = "stopped";
    }

    private void RunVirtual()
    {
        // The session layer's schedule runs the robot's cycle and the loop ticks due on the virtual clock, and the
        // work between cycles (the console's commands); the thread sleeps whenever the virtual clock gets ahead of the
        // wall clock, so the virtual robot runs in real time. It sleeps a millisecond at a time and stops sleeping
        // when an emergency stop is on its way: a piece of work that ran ahead of the wall clock (homing, a parameter
        // reload) must not hold the stop back while its virtual time is slept off.
        var wall = Stopwatch.StartNew();
        var cycleBegin = Stopwatch.GetTimestamp();
        var robot = _session.Robot;
        _session.RunVirtual(long.MaxValue, () =>
        {
            _sessionThread.BusCycle.Record(Stopwatch.GetTimestamp() - cycleBegin);
            while (_events.Now - wall.Elapsed.TotalSeconds > 0.002 && !robot.StopPending && !_stop.IsCancellationRequested)
            {
                Thread.Sleep(1);
            }

            cycleBegin = Stopwatch.GetTimestamp();
        }, StepCountingAllocations, () => _stop.IsCancellationRequested);
    }

    /// <summary>One loop tick (the loop plus the ring recorder), counting what it allocates on this thread.</summary>
    private void StepCountingAllocations(ControlLoop loop, long timestamp)
    {
        var before = GC.GetAllocatedBytesForCurrentThread();
        loop.Step();
        _sessionThread.AddTickAllocation(GC.GetAllocatedBytesForCurrentThread() - before);
    }

    /// <summary>
    /// A real bus: the session layer starts the robot's bus thread and the loop thread, as a run does (one bus loop);
    /// this thread waits for the stop, or for the loop to fail.
    /// </summary>
    private void RunRealTime()
    {
        _session.StartBus(_threads); // code compiled, wake-up latency held until the session's stop, as in a run
        _ownsBus.Set(); // the robot's bus thread owns the bus
        _events.Add("session", $"threads: {_threads.Outcome}{(_session.CpuLatency is { } latency ? "; " + latency : "")}");
        var loop = _session.Loop;
        while (!_stop.Token.WaitHandle.WaitOne(StatusPublisher.Every) && loop.ThreadFailure is null)
        {
        }

        if (loop.ThreadFailure is { } failure)
        {
            throw new InvalidOperationException($"control loop failed: {failure.Message}", failure);
        }
    }

    /// <summary>The loop's observer, given to the session layer before the recorder (which needs the loaded graph) exists.</summary>
    private sealed class ObserverSlot : ITickObserver
    {
        public ITickObserver? Target { get; set; }

        public void AfterTick(in TickContext context) => Target?.AfterTick(in context);
    }
}
