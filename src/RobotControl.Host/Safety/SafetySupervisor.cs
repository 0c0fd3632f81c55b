using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Control.States;

namespace RobotControl.Host.Safety;

/// <summary>
/// Owns the question "is it safe to move?": the run level (<see cref="RunLevels.NewMachine"/>), the operator's commands
/// (home, pedal, emergency stop, reset) and the per-cycle checks, the cycle's step <b>check</b> (<see cref="BusRobot.Check"/>),
/// allocation-free while nothing trips. Outside <see cref="RunLevel.PedalDown"/> the robot holds (teleoperation is
/// ignored); every goal is under the robot layer's step cap. A trip records what crossed which limit, puts the robot
/// in the check's safe state (<see cref="SafetyLimits.SafeStateOf"/>) and moves to <see cref="RunLevel.EStop"/>;
/// nothing leaves it but an operator <see cref="Reset"/>, after which the robot must be homed again (unless only
/// silences caused it and the pots confirm every position). Soft trips go back to <see cref="RunLevel.PedalUp"/>
/// instead, as the Raven-II's master-data timeout forces pedal-up: a host stall, a loop behind or a silent module
/// shorter than the modules' torque-off stage, the master timeout and a master jump, each with its safe state hold
/// (<see cref="Trip"/> grades them); the operator presses the pedal again once the robot is ready. When the graph
/// wires a pedal to the robot node (<see cref="ReportPedal"/>), PEDAL_UP and PEDAL_DOWN follow it (a press moves
/// to PEDAL_DOWN only from PEDAL_UP, so after a timeout or a trip the operator lifts and presses again); an
/// emergency-stop pedal or button (<see cref="ReportEmergencyStop"/>) trips E-STOP when pressed.
/// <para>
/// Threads: the checks run on the bus thread (<see cref="ICycleCheck"/>, step <b>check</b> of the cycle) and decide
/// only: their actions (hold, motors off) are requests the robot's next write takes up, with no bus traffic inside the
/// check. The operator's commands (<see cref="Home"/>, pedal, <see cref="MotorsOff"/>, <see cref="Reset"/>) run on the
/// bus thread too, between cycles. The loop's thread reports the operator's inputs (<see cref="IOperatorPort"/>), kept
/// apart in <see cref="OperatorInputs"/>. An emergency stop never waits: from any thread it is a lock-free request.
/// </para>
/// </summary>
[WrittenBy(RobotThread.Bus)]
public sealed partial class SafetySupervisor : ICycleCheck, IOperatorPort
{
    private const string TripSource = "supervisor";
    private const string PedalSource = "pedal";
    private readonly BusRobot _robot;
    private readonly TimeProvider _time;
    private readonly StateMachine<RunLevel> _levels;
    private readonly TripLog _trips = new();
    private readonly MotorChecks _motorChecks;
    private readonly ModuleChecks _moduleChecks;
    private readonly OperatorInputs _inputs;
    private readonly TripGrading _grading;
    private readonly StallClock _clock;
    private readonly SupervisedHoming _homing;
    private readonly TripRecorder _record; // how the parts record a trip (Trip, with the supervisor as its source)
    private GraphWatch _graph;
    private long _jumpsSeen;
    private volatile bool _torqueOffTaken;
    private OperatorPedal _lastPedal;
    private OperatorPedal _lastEmergencyStop;
    private EmergencyStopRequest? _stopRequest;
    private SafetyTrip? _stopCause; // the trip that moved to E_STOP last

    /// <summary>A supervisor of <paramref name="robot"/> (discovered) at <see cref="RunLevel.Init"/>; it checks every cycle from now on.</summary>
    /// <param name="robot">The robot layer (its clock is the supervisor's).</param>
    /// <param name="limits">Thresholds and safe states (the robot file's <c>safety</c> section).</param>
    /// <param name="loopPeriod">The control loop's period (the unit of deadline misses).</param>
    public SafetySupervisor(BusRobot robot, SafetyLimits limits, TimeSpan loopPeriod)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(limits);
        ArgumentOutOfRangeException.ThrowIfLessThanOrEqual(loopPeriod, TimeSpan.Zero);
        _robot = robot;
        _time = robot.Client.Time;
        Limits = limits;
        LoopPeriod = loopPeriod;
        _levels = RunLevels.NewMachine(_time);
        _grading = new TripGrading(limits, robot.Definition.Modules.WatchdogOffMs); // the modules' torque-off stage (they hold from WatchdogMs)
        _record = (check, joint, measured, limit, unit, now) => Trip(check, joint, measured, limit, unit, now);
        _motorChecks = new MotorChecks(robot, limits, _record);
        _moduleChecks = new ModuleChecks(robot, limits, _record);
        _homing = new SupervisedHoming(robot, _motorChecks, _levels);
        _inputs = new OperatorInputs(robot.ArmCount, limits.MasterSpeedMaxMmPerS, robot.HoldAtSent, _time);
        _clock = new StallClock(_time, (long)(limits.DeadlineMissesInARow * loopPeriod.TotalSeconds * _time.TimestampFrequency), _grading.TorqueOffStageMs, _inputs);
        _graph = new GraphWatch(_clock, _record);
        Origin = _time.GetTimestamp();
        _robot.HoldAtMeasured();
        _robot.CycleCheck = this;
    }

    /// <summary>Thresholds and safe states.</summary>
    public SafetyLimits Limits { get; }

    /// <summary>
    /// Watches the graph that drives the robot (before the threads start): a late loop's trip names the plug-in it
    /// waits for, and a plug-in faulting upstream of <paramref name="node"/> is a trip (<see cref="SafetyCheck.PluginFault"/>).
    /// </summary>
    public void WatchGraph(Runtime.Graph.GraphProgram program, Runtime.Robot.RobotNode node)
    {
        ArgumentNullException.ThrowIfNull(program);
        ArgumentNullException.ThrowIfNull(node);
        _graph = new GraphWatch(_clock, _record, program, node, LoopPeriod.TotalMilliseconds);
    }

    /// <summary>The control loop's period.</summary>
    public TimeSpan LoopPeriod { get; }

    /// <summary>The timestamp reports count time from (the supervisor's creation until <see cref="SetOrigin"/>).</summary>
    public long Origin { get; private set; }

    /// <summary>The run level now.</summary>
    public RunLevel Level => _levels.Current;

    /// <summary>Every run-level change, oldest first.</summary>
    public IReadOnlyList<StateTransition<RunLevel>> History => _levels.History;

    /// <summary>Run-level changes so far, without a lock or a copy (poll this, copy <see cref="History"/> when it grew).</summary>
    public int HistoryCount => _levels.MoveCount;

    /// <summary>Trips so far, without a lock or a copy (poll this, copy <see cref="Trips"/> when it grew).</summary>
    public int TripCount => _trips.Count;

    /// <summary>Every trip, oldest first (a copy).</summary>
    public IReadOnlyList<SafetyTrip> Trips => _trips.All;

    /// <summary>What the loop's thread reported (tests read the input ages from it).</summary>
    internal OperatorInputs Inputs => _inputs;

    /// <summary>The robot layer supervised.</summary>
    public BusRobot Robot => _robot;

    /// <summary>True once a trip has switched the motors off (until the next <see cref="Home"/>): the arms cannot move.</summary>
    public bool MotorsTrippedOff => _torqueOffTaken;

    /// <summary>Seconds from <see cref="Origin"/> to <paramref name="timestamp"/> (negative before it).</summary>
    public double Seconds(long timestamp) => (timestamp - Origin) / (double)_time.TimestampFrequency;

    /// <summary>Makes <paramref name="timestamp"/> the origin of report times (the start of a run).</summary>
    public void SetOrigin(long timestamp) => Origin = timestamp;

    /// <summary>
    /// Every trip goes through here, graded (<see cref="TripGrading"/>): a soft one holds (<see cref="SoftTrip"/>); any
    /// other records what crossed which limit, takes its safe state at the next write and moves to E_STOP; each check
    /// trips once until a reset.
    /// </summary>
    private void Trip(SafetyCheck check, string joint, double measured, double limit, string unit, long now, string source = TripSource, string? reason = null)
    {
        (var action, limit, var soft) = _grading.Grade(check, measured, limit);
        if (soft)
        {
            SoftTrip(check, joint, measured, limit, unit, now);
            return;
        }

        if (_trips.TryRecord(now, check, joint, measured, limit, unit, action) is not { } trip)
        {
            return;
        }

        var torqueOff = action == SafeState.TorqueOff && !_torqueOffTaken;
        _torqueOffTaken |= torqueOff;
        _robot.EmergencyHold($"{check.Name()} {joint}".TrimEnd() + $": {action.Name()}", torqueOff); // taken at the next write, before any queued work

        if (Level != RunLevel.EStop)
        {
            _stopCause = trip;
            _levels.MoveTo(RunLevel.EStop, source, reason ?? $"{check.Name()} {joint}".TrimEnd() + $": {action.Name()}");
        }
    }

    /// <summary>
    /// A soft trip, as the Raven-II treats a stale master: the arms hold at the goals last sent (from the next write, or
    /// this one when taken before it), the run level goes back from PEDAL_DOWN to PEDAL_UP, and the operator may press the pedal again;
    /// re-engaging starts from the held positions (the graph's clutch re-offsets the master, see the robot node's
    /// <c>teleop_enabled</c>). Each check is recorded once per episode of teleoperation (until the next pedal down): the
    /// one that ended it, not every cycle it stays true (a cycle slowed by a silent module's timeouts is a gap too).
    /// </summary>
    private void SoftTrip(SafetyCheck check, string joint, double measured, double limit, string unit, long now)
    {
        if (_trips.TryRecordSoft(now, check, joint, measured, limit, unit) is not { } trip)
        {
            return;
        }

        _robot.HoldAtSent(); // where the arms were going: re-engaging from the setpoints of before the trip cannot step
        if (Level == RunLevel.PedalDown)
        {
            _levels.MoveTo(RunLevel.PedalUp, TripSource, trip.ToString());
        }
    }

    /// <summary>An emergency stop asked for from another thread (<see cref="EmergencyStop"/>).</summary>
    private sealed record EmergencyStopRequest(string Source, string Reason);
}
