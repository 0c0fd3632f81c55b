using System.Runtime.CompilerServices;
using RobotControl.Bus.Client;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Coupling;
using RobotControl.Robot.Control;
using RobotControl.Robot.Control.States;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// A robot on its module bus, as one facade over the parts of the robot core, each of which owns its state and says
/// which thread writes it (<see cref="WrittenByAttribute"/>):
/// <list type="bullet">
/// <item><see cref="SetpointExchange"/>: the setpoints, written by the control loop's thread (<see cref="IRobotPort"/>).</item>
/// <item><see cref="GoalWriter"/>: step <b>write</b> (goals, hold, step cap, encoding), on the bus thread; takes up
/// the requests other threads make (a stop, a hold, the motors off, faults cleared).</item>
/// <item><see cref="FeedbackExchange"/>: steps <b>read</b> and <b>publish</b>, on the bus thread.</item>
/// <item><see cref="ModuleSupervisor"/>: status, pots, resets, watchdogs, missing modules, after each publish.</item>
/// <item><see cref="RobotSetup"/> and <see cref="Homing"/>: discovery, parameters, torque, homing, driven by the
/// state machine (<see cref="RobotLifecycle"/>), run between cycles (<see cref="BetweenCycles"/>).</item>
/// </list>
/// The cycle is write, read, publish, check (<see cref="ICycleCheck"/>, the safety supervisor), then one piece of the
/// work between cycles; the bus thread (<see cref="Start(Action)"/>), <see cref="RunFor"/> and the virtual schedule
/// all run this one cycle. A set-up call made from another thread while a thread owns the bus is queued for it and
/// waited for; an emergency stop never waits (<see cref="EmergencyHold"/>).
/// </summary>
public sealed class BusRobot : IRobotPort, IBusCycle, IDisposable
{
    /// <summary>
    /// Retries of a transaction that must get through: the arming writes and a stop's torque-off and read-back
    /// (12 transactions in all, up to about 10 ms at 1 Mbaud). Switching the motors on or off is set-up, not the cycle,
    /// and one stalled reply must not leave a robot half-armed or a stop unverified (a pty simulator in another process
    /// missed whole transactions under load). A refusal (an answer with an error) is final.
    /// </summary>
    public const int InsistingRetries = 11;

    private readonly BusClient _client;
    private readonly BusRobotOptions _options;
    private readonly TimeProvider _time;
    private readonly RobotLayout _layout;
    private readonly ModuleRoster _roster;
    private readonly RobotLifecycle _life;
    private readonly RobotFaultFlags _faults;
    private readonly SetpointExchange _setpoints;
    private readonly FeedbackExchange _feedback;
    private readonly GoalWriter _goals;
    private readonly ModuleSupervisor _modules;
    private readonly RobotSetup _setup;
    private readonly Homing _homing;
    private readonly BusInterruption _stop = new();
    private readonly BusThread _thread;
    private long _cycles;

    /// <summary>Opens <paramref name="robot"/> on the bus <paramref name="client"/> talks to (the robot owns the client).</summary>
    /// <exception cref="ArgumentException">The robot file has no modules section.</exception>
    public BusRobot(RobotDefinition robot, BusClient client, BusRobotOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(client);
        if (robot.Modules.Modules.Count == 0)
        {
            throw new ArgumentException($"{robot.SourceFile}: the robot file has no modules section; nothing to drive on the bus", nameof(robot));
        }

        _client = client;
        _time = client.Time;
        _options = options ?? new BusRobotOptions();
        _layout = new RobotLayout(robot);
        _roster = new ModuleRoster(_layout);
        _life = new RobotLifecycle(_time);
        var seed = new GoalSeed(_layout);
        _feedback = new FeedbackExchange(_layout, client, _roster, _options, Events);
        _setpoints = new SetpointExchange(_layout, _feedback, seed);
        _faults = new RobotFaultFlags(_setpoints);
        var arming = new ModuleArming(_layout, client, _roster, Events);
        _modules = new ModuleSupervisor(_layout, client, _roster, _options, Events, _faults, _life, arming);
        _setup = new RobotSetup(_layout, client, _roster, Events, _faults, _life, arming, _modules, _feedback, _setpoints, seed);
        _homing = new Homing(_layout, client, _roster, _life, _setup, _feedback);
        _goals = new GoalWriter(_layout, client, _roster, _setpoints, seed, _life, _stop)
        {
            TorqueOff = _setup.TorqueOffAtWrite,
            Clear = _modules.ClearInModules,
            AcknowledgeHold = _modules.AcknowledgeHold,
        };
        Slot = new BetweenCycles(client, _stop);
        _thread = new BusThread(this, _options, _time);
    }

    /// <inheritdoc />
    public RobotDefinition Definition => _layout.Definition;

    /// <inheritdoc />
    public int ArmCount => _layout.ArmCount;

    /// <summary>The protocol client.</summary>
    public BusClient Client => _client;

    /// <summary>Every configured controller, in file order.</summary>
    public IReadOnlyList<RobotController> Controllers => _layout.Controllers;

    /// <summary>Every configured motor.</summary>
    public IReadOnlyList<RobotMotor> Motors => _layout.Motors;

    /// <summary>The joint &lt;-&gt; motor mapping.</summary>
    public JointMotorMap Map => _layout.Map;

    /// <summary>Completed bus cycles.</summary>
    public long Cycles => Interlocked.Read(ref _cycles);

    /// <summary>Things that happened (discovery problems, module reset, missing, back, watchdog, bus errors): subscribe to read them.</summary>
    public RobotEventStream Events { get; } = new();

    /// <summary>The work between cycles: set-up and commands that must run on the bus's owner.</summary>
    public BetweenCycles Slot { get; }

    /// <summary>The per-cycle check (the safety supervisor), run by step <see cref="Check"/>.</summary>
    public ICycleCheck? CycleCheck { get; set; }

    /// <summary>The robot's state now.</summary>
    public RobotState State => _life.State;

    /// <summary>Every state change so far with its time, source and reason, oldest first.</summary>
    public IReadOnlyList<StateTransition<RobotState>> StateHistory => _life.Machine.History;

    /// <inheritdoc />
    public RobotFaults Faults => _faults.Value;

    /// <summary>Goals the step cap shortened so far (one per motor and write).</summary>
    public long StepCapHits => _goals.StepCapHits;

    /// <summary>The largest step asked of a motor in one write that the cap shortened, output radians (0: none).</summary>
    public double LargestCappedStepRad => _goals.LargestCappedStepRad;

    /// <summary>True while the goals are frozen (<see cref="HoldAtMeasured"/>, <see cref="HoldAtSent"/>), from the request on.</summary>
    public bool IsHolding => _goals.IsHolding;

    /// <summary>
    /// Present modules holding their motors on their own, as the status poll last found them: no frame reached them for
    /// the robot file's <c>modules.watchdog_ms</c> (the firmware's bus watchdog, first stage: <c>hardware_error_status</c>
    /// bit <c>bus_hold</c>, read with the status the poll reads anyway). A holding module refuses goals and torque-on
    /// until the hold is acknowledged (<see cref="RequestHoldAcknowledgement"/>) and switches its motors off after
    /// <c>modules.watchdog_off_ms</c> without a frame. Written by the bus thread, read by any thread; per module:
    /// <see cref="RobotController.BusHold"/>.
    /// </summary>
    public int ModulesHolding => _modules.Holding;

    /// <summary>
    /// True from an emergency stop's request (<see cref="EmergencyHold"/>) until the write that takes it: whoever runs
    /// the cycle must not wait now (a virtual schedule pacing itself to the wall clock stops sleeping).
    /// </summary>
    public bool StopPending => _stop.IsRaised;

    /// <summary>Methods the JIT compiled on the bus thread after its first cycle; known once the thread has ended (<see cref="Stop"/>).</summary>
    public long MethodsCompiledAfterFirstCycle => _thread.MethodsCompiledAfterFirstCycle;

    /// <summary>Time the bus thread spent in the JIT after its first cycle.</summary>
    public TimeSpan CompileTimeAfterFirstCycle => _thread.CompileTimeAfterFirstCycle;

    /// <summary>The motor named <c>arm.joint</c>, e.g. <c>right.elbow</c>.</summary>
    /// <exception cref="KeyNotFoundException">No such motor.</exception>
    public RobotMotor Motor(string fullName) =>
        _layout.Motors.FirstOrDefault(m => m.Config.FullName == fullName)
        ?? throw new KeyNotFoundException($"no motor '{fullName}' (motors: {string.Join(", ", _layout.Motors.Select(m => m.Config.FullName))})");

    /// <summary>The controller with bus ID <paramref name="id"/>, or null.</summary>
    public RobotController? Controller(byte id) => _layout.Controllers.FirstOrDefault(c => c.Id == id);

    /// <summary>The step cap of <paramref name="motor"/> over <paramref name="seconds"/>: its maximum output speed times the time, radians.</summary>
    public static double StepCapRad(RobotMotor motor, double seconds)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return motor.SpeedLimitRadS * seconds;
    }

    /// <summary>The goal last sent to <paramref name="motor"/>, output radians (its position before the first write).</summary>
    public double SentGoalRad(RobotMotor motor)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return _goals.HasWritten ? _goals.SentGoal(motor.Index) : motor.PositionRad;
    }

    /// <summary>
    /// The goal the control loop's setpoints ask of <paramref name="motor"/>, output radians (its position before the
    /// first write): what it follows out of manual, and so where <see cref="RobotMotor.ReleaseManual"/> sends it.
    /// </summary>
    public double LoopGoalRad(RobotMotor motor)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return _goals.HasWritten ? _goals.LoopGoal(motor.Index) : motor.PositionRad;
    }

    // --- requests any thread may make, taken up at the next write -------------------------------------------------

    /// <summary>Freezes every motor's goal at its measured position from the next write on; the setpoints are ignored until <see cref="ReleaseHold"/>.</summary>
    public void HoldAtMeasured() => _goals.HoldAtMeasured();

    /// <summary>
    /// Freezes every motor's goal at the goal last sent from the next write on (any thread, lock-free): a soft trip's
    /// hold, so that re-engaging from the setpoints of before it cannot step; the setpoints are ignored until
    /// <see cref="ReleaseHold"/>. Before any write, the measured positions.
    /// </summary>
    public void HoldAtSent() => _goals.HoldAtSent();

    /// <summary>The setpoints drive the goals again (each still under the step cap).</summary>
    public void ReleaseHold() => _goals.ReleaseHold();

    /// <summary>The motors go off at the next write (a supervisor's safe state); a refusal is an event, never an exception.</summary>
    public void RequestTorqueOff(string reason) => _goals.RequestTorqueOff(reason);

    /// <summary>Clears latched faults here and in the modules at the next write, re-arming them if torque was on.</summary>
    public void ClearFaults() => _goals.RequestClear();

    /// <summary>
    /// Clears latched faults here and in the modules now, as <see cref="ClearFaults"/> does at the next write (on the
    /// bus's owner: queued between cycles when called from another thread): an operator's reset, so that what comes
    /// next (homing, motors on) finds the modules cleared.
    /// </summary>
    public void ClearFaultsNow() => Slot.Run("clear faults", _modules.ClearInModules);

    /// <summary>
    /// Acknowledges the modules' bus holds (<see cref="ModulesHolding"/>) at the next write, on the bus thread, before that
    /// write's goals (any thread, lock-free): each holding module gets <c>hardware_error_status</c> 0 and follows the goals
    /// from then on, its motors' step cap starting from where they held (the goals sent during the hold were refused);
    /// a module with another latched error keeps holding until <see cref="ClearFaults"/>. To stay where the modules held
    /// instead of resuming toward the setpoints, hold at the measured positions first (<see cref="HoldAtMeasured"/>).
    /// Each module acknowledged is an event (<see cref="Events.HoldAcknowledged"/>).
    /// </summary>
    public void RequestHoldAcknowledgement() => _goals.RequestHoldAcknowledgement();

    /// <summary>
    /// Acknowledges the modules' bus holds now, as <see cref="RequestHoldAcknowledgement"/> does at the next write (on the
    /// bus's owner: queued between cycles when called from another thread): set-up that turns the motors on (homing)
    /// finds the modules following again; they refuse torque-on while they hold.
    /// </summary>
    public void AcknowledgeHoldsNow() => Slot.Run("acknowledge holds", _goals.AcknowledgeHoldsNow);

    /// <summary>
    /// An emergency stop's action, from any thread, lock-free: hold at the measured positions (and, with
    /// <paramref name="torqueOff"/>, the motors off) at the next write, and the piece of work running between cycles
    /// cut short at its next transaction; no queued work starts before the next write.
    /// </summary>
    public void EmergencyHold(string reason, bool torqueOff) => _goals.EmergencyHold(reason, torqueOff);

    // --- set-up, run by the bus's owner -------------------------------------------------------------------------------

    /// <summary>
    /// Broadcast-pings the bus and compares what answers with the robot file: missing, unknown and mismatched modules
    /// are listed (each problem also in <see cref="Events"/>); present ones take part in the cycles. Moves the robot to
    /// <see cref="RobotState.Discovered"/>.
    /// </summary>
    /// <exception cref="InvalidOperationException">The motors are on (turn them off first) or homing runs.</exception>
    public DiscoveryReport Discover() => Slot.Run("discovery", _setup.Discover);

    /// <summary>Reads every present module's persistent area and lists the values that differ from the robot file.</summary>
    public IReadOnlyList<ParameterMismatch> CheckParameters() => Slot.Run("checking parameters", _setup.CheckParameters);

    /// <summary>Writes the robot file's parameters into every present module's FRAM (each write is durable when acknowledged); returns how many.</summary>
    /// <exception cref="IOException">A module refused or did not acknowledge a value.</exception>
    public int WriteParameters() => Slot.Run("writing parameters", _setup.WriteParameters);

    /// <summary>
    /// Writes one persistent parameter of one motor (or module-wide field) and reads it back, through the one
    /// parameter path (<see cref="RobotControl.Modules.ParameterWriter"/>): a value that switches a protection off (a current limit of 0,
    /// ...) only with <paramref name="allowProtectionOff"/>, which the console never passes.
    /// </summary>
    /// <exception cref="ArgumentException">A rule refuses the value (<see cref="RobotControl.Modules.ParameterRules"/>); nothing was written.</exception>
    /// <exception cref="IOException">The module refused the value or read back something else.</exception>
    public long WriteParameter(byte moduleId, string field, int motor, long value, bool allowProtectionOff = false) =>
        Slot.Run($"writing {field}[{motor}] of module {moduleId}", () => _setup.WriteParameter(moduleId, field, motor, value, allowProtectionOff));

    /// <summary>Reads one control-table value.</summary>
    /// <exception cref="IOException">The module does not answer.</exception>
    public long ReadParameter(byte moduleId, string field, int motor = 0) =>
        Slot.Run($"reading {field}[{motor}] of module {moduleId}", () => _setup.ReadParameter(moduleId, field, motor));

    /// <summary>
    /// Turns the motors on (arming each module's bus watchdog) or off. Turning on starts every goal from the present
    /// position (a seed the next write takes up), so nothing moves until the control loop or a manual command says so.
    /// </summary>
    /// <exception cref="IOException">A module refuses (e.g. its watchdog error is latched: clear faults first).</exception>
    /// <exception cref="InvalidOperationException">On: not discovered, homing, or in <see cref="RobotState.Fault"/>. Off: homing runs.</exception>
    public void EnableTorque(bool on) => Slot.Run(on ? "motors on" : "motors off", () => _setup.EnableTorque(on));

    /// <summary>Homes every motor of the present modules from its joint pot and verifies the result, motor by motor (see <see cref="Homing"/>).</summary>
    /// <exception cref="InvalidOperationException">Torque is on: turn it off first (a driven motor must not change coordinates).</exception>
    public IReadOnlyList<HomingResult> Home() => Slot.Run("homing", _homing.HomeAll);

    /// <summary>Homes one motor from its pot (its module's home request for its channel alone), motors off.</summary>
    public HomingResult HomeMotor(RobotMotor motor)
    {
        ArgumentNullException.ThrowIfNull(motor);
        return Slot.Run($"homing {motor.Config.FullName}", () => _homing.HomeOne(motor));
    }

    /// <summary>Reboots one module (motors off).</summary>
    public Reply Reboot(byte moduleId) => Slot.Run($"rebooting module {moduleId}", () => _setup.Reboot(moduleId));

    // --- the cycle ----------------------------------------------------------------------------------------------------

    /// <summary>Runs bus cycles on a thread of its own until <see cref="Stop"/> (real links).</summary>
    public void Start() => Start(static () => { });

    /// <summary>Runs bus cycles on a thread of its own until <see cref="Stop"/>; the thread first runs <paramref name="prologue"/> (e.g. real-time scheduling).</summary>
    public void Start(Action prologue) => _thread.Start(prologue);

    /// <summary>Stops the bus thread; work still queued for it fails.</summary>
    public void Stop() => _thread.Stop();

    /// <summary>True while the bus thread runs (it ends on <see cref="Stop"/>).</summary>
    public bool IsRunning => _thread.IsRunning;

    /// <summary>
    /// Runs bus cycles on the calling thread, which owns the bus meanwhile, until <paramref name="duration"/> has passed
    /// on the client's clock (a virtual bus advances its simulated clock as the cycles wait for bytes).
    /// </summary>
    public void RunFor(TimeSpan duration)
    {
        using var own = OwnBus();
        var target = _time.GetTimestamp() + (long)(duration.TotalSeconds * _time.TimestampFrequency);
        Span<byte> idle = stackalloc byte[16];
        while (_time.GetTimestamp() < target)
        {
            if (!_roster.Active.Any)
            {
                // Nothing to talk to: let the time pass on the link (a virtual bus simulates meanwhile).
                var left = target - _time.GetTimestamp();
                _client.Link.Read(idle, TimeSpan.FromSeconds(left / (double)_time.TimestampFrequency));
                RunBetweenCycles();
                continue;
            }

            RunCycle();
        }
    }

    /// <summary>One cycle: write, read, publish, check, then one piece of the work between cycles.</summary>
    public void RunCycle()
    {
        Write();
        Read();
        Publish();
        Check();
        RunBetweenCycles();
    }

    /// <inheritdoc />
    public void Write()
    {
        CycleCheck?.BeforeWrite();
        _goals.Write();
    }

    /// <inheritdoc />
    public void Read() => _feedback.Read();

    /// <inheritdoc />
    public void Publish()
    {
        _feedback.Publish(_faults);
        var cycle = Interlocked.Increment(ref _cycles);
        _modules.AfterPublish(cycle, _feedback.Alert);
    }

    /// <inheritdoc />
    public void Check() => CycleCheck?.Check();

    /// <inheritdoc />
    public void RunBetweenCycles() => Slot.RunNext();

    /// <inheritdoc />
    public IDisposable OwnBus() => Slot.Own();

    /// <summary>
    /// A failed cycle (the link said <paramref name="ex"/>): the bus degraded and every present module's reply missed
    /// until a cycle succeeds, and step <b>check</b> still runs, so the supervisor takes its safe state when the
    /// silence lasts (module silent). With <paramref name="report"/>, a bus error event too (the bus thread reports a
    /// failure that repeats once a second, with how many it left out).
    /// </summary>
    internal void CycleFailed(IOException ex, bool report, int leftOut)
    {
        if (report)
        {
            Events.Publish(new BusError(leftOut == 0 ? ex.Message : $"{ex.Message} ({leftOut} more failed cycles since the last report)"));
        }

        _feedback.CycleLost(_faults);
        Slot.LinkFailedThisCycle(ex.Message); // queued commands fail now and new ones are refused: nobody waits on a dead link
        Check();
    }

    // --- the control loop's side (IRobotPort) ---------------------------------------------------------------------

    /// <inheritdoc />
    public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad) => _setpoints.WriteJoints(arm, jointsRad);

    /// <inheritdoc />
    public void WriteJawSetpoint(int arm, double jawRad) => _setpoints.WriteJaw(arm, jawRad);

    /// <inheritdoc />
    public void ReadJointPositions(int arm, Span<double> jointsRad) => _feedback.ReadJoints(arm, jointsRad);

    /// <inheritdoc />
    public void ReadMotorCurrents(int arm, Span<double> currentsA) => _feedback.ReadCurrents(arm, currentsA);

    /// <inheritdoc />
    public void HoldPosition() => _setpoints.HoldAtFeedback();

    /// <summary>The setpoint exchange (tests watch what the bus thread reads from it).</summary>
    internal SetpointExchange Setpoints => _setpoints;

    /// <inheritdoc />
    public void Dispose()
    {
        Stop();
        _client.Dispose();
    }
}
