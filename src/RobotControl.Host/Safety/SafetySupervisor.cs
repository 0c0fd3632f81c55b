using System.Globalization;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Host.Safety;

/// <summary>
/// Owns the question "is it safe to move?": the run level (<see cref="RunLevelMachine"/>), the operator's commands
/// (home, pedal, emergency stop, reset) and the per-cycle checks, which run inside the bus cycle between read and
/// write (<see cref="BusRobot.AfterUpdate"/>), allocation-free while nothing trips. Outside
/// <see cref="RunLevel.PedalDown"/> the robot holds (goals frozen at the measured positions: teleoperation is
/// ignored); every goal is under the robot layer's step cap. A trip records what crossed which limit, puts the robot
/// in the check's safe state (<see cref="SafetyLimits.SafeStateOf"/>) and moves to <see cref="RunLevel.EStop"/>;
/// nothing leaves it but an operator <see cref="Reset"/>, after which the robot must be homed again. The master
/// timeout (input device data older than its limit, <see cref="BusRobot.InputAgeMs"/>) is the one soft trip that,
/// with its default safe state hold, goes back to <see cref="RunLevel.PedalUp"/> instead (as the Raven-II's
/// master-data timeout forces pedal-up): the operator may press the pedal again once the data is fresh. When the graph
/// wires a pedal to the robot node (<see cref="BusRobot.Pedal"/>), PEDAL_UP and PEDAL_DOWN follow it (a press moves
/// to PEDAL_DOWN only from PEDAL_UP, so after a timeout or a trip the operator lifts and presses again); an
/// emergency-stop pedal or button (<see cref="BusRobot.EmergencyStopPedal"/>) trips E-STOP when pressed.
/// </summary>
public sealed class SafetySupervisor
{
    private const string TripSource = "supervisor";
    private const string PedalSource = "pedal";
    private readonly BusRobot _robot;
    private readonly TimeProvider _time;
    private readonly RunLevelMachine _levels;
    private readonly List<SafetyTrip> _trips = new(32);
    private readonly Lock _tripGate = new();
    private readonly RobotMotor[] _motors;
    private readonly RobotController[] _controllers;
    private readonly string[] _motorNames;
    private readonly string[] _controllerNames;
    private readonly long[] _trackingSince;
    private readonly long[] _currentSince;
    private readonly long[] _potSince;
    private readonly double[] _trackingLimit;
    private readonly double[] _potLimit;
    private readonly long[] _answeredAt;
    private readonly bool[] _tripped = new bool[Enum.GetValues<SafetyCheck>().Length];
    private readonly long _trackingTicks;
    private readonly long _currentTicks;
    private readonly long _potTicks;
    private readonly long _silentTicks;
    private readonly long _stallTicks;
    private readonly int _arms;
    private long _lastCycle;
    private volatile bool _torqueOffTaken;
    private bool _mustRehome;
    private OperatorPedal _lastPedal;
    private OperatorPedal _lastEmergencyStop;

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
        _levels = new RunLevelMachine(_time);
        _motors = [.. robot.Motors];
        _controllers = [.. robot.Controllers];
        _motorNames = [.. _motors.Select(m => m.Config.FullName)];
        _controllerNames = [.. _controllers.Select(c => $"{ArmName(robot, c)}.{c.Definition.Location}")];
        _trackingSince = new long[_motors.Length];
        _currentSince = new long[_motors.Length];
        _potSince = new long[_motors.Length];
        _trackingLimit = [.. _motorNames.Select(limits.TrackingErrorRadOf)];
        _potLimit = [.. _motorNames.Select(limits.PotDistanceRadOf)];
        _answeredAt = new long[_controllers.Length];
        var f = _time.TimestampFrequency;
        _trackingTicks = (long)(limits.TrackingErrorMs * 1e-3 * f);
        _currentTicks = (long)(limits.OverCurrentMs * 1e-3 * f);
        _potTicks = (long)(limits.PotMismatchMs * 1e-3 * f);
        _silentTicks = (long)(limits.ModuleSilentMs * 1e-3 * f);
        _stallTicks = (long)(limits.DeadlineMissesInARow * loopPeriod.TotalSeconds * f);
        _arms = robot.ArmCount;
        Origin = _time.GetTimestamp();
        _robot.HoldAtMeasured();
        _robot.AfterUpdate = CheckCycle;
    }

    /// <summary>Thresholds and safe states.</summary>
    public SafetyLimits Limits { get; }

    /// <summary>The control loop's period.</summary>
    public TimeSpan LoopPeriod { get; }

    /// <summary>The timestamp reports count time from (the supervisor's creation until <see cref="SetOrigin"/>).</summary>
    public long Origin { get; private set; }

    /// <summary>The run level now.</summary>
    public RunLevel Level => _levels.Current;

    /// <summary>Every run-level change, oldest first.</summary>
    public IReadOnlyList<RunLevelTransition> History => _levels.History;

    /// <summary>Every trip, oldest first (a copy).</summary>
    public IReadOnlyList<SafetyTrip> Trips
    {
        get
        {
            lock (_tripGate)
            {
                return [.. _trips];
            }
        }
    }

    /// <summary>The robot layer supervised.</summary>
    public BusRobot Robot => _robot;

    /// <summary>True once a trip has switched the motors off (until the next <see cref="Home"/>): the arms cannot move.</summary>
    public bool MotorsTrippedOff => _torqueOffTaken;

    /// <summary>Seconds from <see cref="Origin"/> to <paramref name="timestamp"/> (negative before it).</summary>
    public double Seconds(long timestamp) => (timestamp - Origin) / (double)_time.TimestampFrequency;

    /// <summary>Makes <paramref name="timestamp"/> the origin of report times (the start of a run).</summary>
    public void SetOrigin(long timestamp) => Origin = timestamp;

    /// <summary>
    /// INIT -> HOMING -> PEDAL_UP: motors off; homed from the pots and verified where positions may be lost (always
    /// after a <see cref="Reset"/>; otherwise when a motor's module reports position lost or a pot mismatch); motors
    /// on, holding the measured positions. Homing that does not verify every motor returns to INIT.
    /// </summary>
    /// <exception cref="InvalidOperationException">Not at INIT, or homing incomplete (the message says how many motors failed).</exception>
    public IReadOnlyList<HomingResult> Home(string source)
    {
        if (Level == RunLevel.EStop)
        {
            var trips = Trips;
            var trip = trips.Count > 0 ? trips[0] : null;
            throw new InvalidOperationException(trip is null
                ? $"homing ({source}) refused: the run level is E_STOP; an operator reset comes first"
                : string.Create(CultureInfo.InvariantCulture, $"homing ({source}) refused: E_STOP since the {trip.Check.Name()} trip {trip.Joint} ({trip.Measured:0.###} {trip.Unit}, limit {trip.Limit:0.###})").Replace("  ", " ", StringComparison.Ordinal) + "; an operator reset comes first");
        }

        _levels.MoveTo(RunLevel.Homing, source, "homing from the joint pots");
        _robot.HoldAtMeasured();
        if (_robot.State == RobotState.Enabled)
        {
            _robot.EnableTorque(false);
        }

        var lost = _mustRehome ? _motors.Length : PositionsInDoubt();
        if (lost == 0)
        {
            _robot.HoldAtMeasured();
            _robot.EnableTorque(true);
            _torqueOffTaken = false;
            _levels.MoveTo(RunLevel.PedalUp, source, $"no module reports a lost position or a pot mismatch: not re-homed; motors on, holding");
            return [];
        }

        var results = _robot.Home();
        var failed = results.Count(r => !r.Succeeded);
        if (failed > 0 || _robot.State != RobotState.Homed)
        {
            _levels.MoveTo(RunLevel.Init, source, $"homing incomplete: {failed} of {results.Count} motors not homed");
            throw new InvalidOperationException($"homing incomplete: {failed} of {results.Count} motors not homed; the run level stays INIT");
        }

        _mustRehome = false;
        _robot.HoldAtMeasured();
        _robot.EnableTorque(true);
        _torqueOffTaken = false;
        _levels.MoveTo(RunLevel.PedalUp, source, $"{results.Count} motors homed and verified ({(lost == _motors.Length ? "after a reset" : $"{lost} had lost their position")}); motors on, holding");
        return results;
    }

    /// <summary>PEDAL_UP -> PEDAL_DOWN: teleoperation drives the arms (from the measured positions, under the step cap).</summary>
    /// <exception cref="InvalidOperationException">Not at PEDAL_UP, or an arm's input device data is older than the master timeout.</exception>
    public void PedalDown(string source)
    {
        if (!_levels.CanMoveTo(RunLevel.PedalDown))
        {
            throw new InvalidOperationException($"pedal down ({source}) needs the run level PEDAL_UP, it is {Level.Name()}");
        }

        if (StaleArm() is { } stale)
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"pedal down ({source}) refused: the input data of the {_robot.Definition.Arms[stale.Arm].Name} arm is {stale.AgeMs:0.#} ms old (master_timeout_ms {Limits.MasterTimeoutMs:0.#})"));
        }

        lock (_tripGate)
        {
            _tripped[(int)SafetyCheck.MasterTimeout] = false; // a new episode of teleoperation: a new timeout is a new trip
        }

        _robot.ReleaseHold();
        _levels.MoveTo(RunLevel.PedalDown, source, "pedal down: teleoperation drives the arms");
    }

    /// <summary>PEDAL_DOWN -> PEDAL_UP: the arms hold where they are; teleoperation is ignored.</summary>
    public void PedalUp(string source, string reason = "pedal up: holding position")
    {
        if (Level != RunLevel.PedalDown)
        {
            return;
        }

        _robot.HoldAtMeasured();
        _levels.MoveTo(RunLevel.PedalUp, source, reason);
    }

    /// <summary>
    /// PEDAL_UP or PEDAL_DOWN -> INIT: an operator turns the motors off without an emergency (e.g. to write persistent
    /// parameters or rediscover the bus); <see cref="Home"/> turns them on again. At E_STOP or INIT the motors are
    /// turned off and the run level stays.
    /// </summary>
    /// <exception cref="InvalidOperationException">Homing runs.</exception>
    public void MotorsOff(string source)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(source);
        if (Level == RunLevel.Homing)
        {
            throw new InvalidOperationException($"motors off ({source}): homing runs, wait for it to end");
        }

        PedalUp(source, "pedal up: the motors go off");
        _robot.HoldAtMeasured();
        if (_robot.State is RobotState.Enabled or RobotState.Fault)
        {
            _robot.EnableTorque(false);
        }

        if (Level == RunLevel.PedalUp)
        {
            _levels.MoveTo(RunLevel.Init, source, "motors off: they go on again through homing (re-homed if positions are in doubt)");
        }
    }

    /// <summary>An operator's emergency stop (console, CLI or pedal): the operator check's safe state, then E-STOP.</summary>
    public void EmergencyStop(string source, string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(source);
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        Trip(SafetyCheck.Operator, string.Empty, 0, 0, string.Empty, _time.GetTimestamp(), source, reason);
    }

    /// <summary>
    /// Leaves E-STOP for INIT, on an operator's explicit request: motors off, faults cleared. The robot must be homed
    /// again (<see cref="Home"/>) before it may move: positions may have been lost.
    /// </summary>
    /// <exception cref="InvalidOperationException">Not at E-STOP.</exception>
    public void Reset(string source)
    {
        if (Level != RunLevel.EStop)
        {
            throw new InvalidOperationException($"reset ({source}) applies at E_STOP only, the run level is {Level.Name()}");
        }

        if (_robot.State is RobotState.Enabled or RobotState.Fault)
        {
            _robot.EnableTorque(false);
        }

        _robot.ClearFaults();
        _mustRehome = true;
        lock (_tripGate)
        {
            Array.Clear(_tripped);
        }

        Array.Clear(_trackingSince);
        Array.Clear(_currentSince);
        Array.Clear(_potSince);
        _levels.MoveTo(RunLevel.Init, source, "operator reset: motors off, faults cleared; homing needed before motion");
    }

    /// <summary>
    /// Motors whose module said at discovery or since (its latched <c>hardware_error_status</c>) that a position may
    /// be wrong (position lost or pot mismatch); a module that is not present counts all its motors. No bus traffic.
    /// </summary>
    private int PositionsInDoubt()
    {
        var doubt = 0;
        foreach (var c in _controllers)
        {
            if (!c.Present || ((HardwareErrors)c.HardwareErrorStatus).HasAny(HardwareErrors.PositionLost | HardwareErrors.PotMismatch))
            {
                doubt += c.Motors.Count;
            }
        }

        return doubt;
    }

    /// <summary>The per-cycle checks (the robot's <see cref="BusRobot.AfterUpdate"/>).</summary>
    private void CheckCycle()
    {
        FollowOperator();
        if (Level == RunLevel.Init)
        {
            _lastCycle = 0;
            return; // motors off and nothing commanded: the checks start with homing
        }

        var now = _time.GetTimestamp();
        var gap = _lastCycle == 0 ? 0 : now - _lastCycle;
        // Cycles are timed only while the motors hold or follow teleoperation (PEDAL_UP, PEDAL_DOWN): set-up and
        // homing run the bus at their own pace (first calls, homing moves), with the motors off or firmware-driven.
        _lastCycle = Level is RunLevel.PedalUp or RunLevel.PedalDown ? now : 0;
        if (gap > _stallTicks)
        {
            Trip(SafetyCheck.DeadlineMiss, string.Empty, Ms(gap), Ms(_stallTicks), "ms", now);
        }

        CheckModules(now);
        if (_robot.State == RobotState.Fault)
        {
            Trip(SafetyCheck.ModuleFault, string.Empty, (double)_robot.Faults, 0, "fault flags", now);
        }

        if ((_robot.Faults & RobotFaults.SetpointRejected) != 0)
        {
            Trip(SafetyCheck.NonFinite, "setpoint", double.NaN, 0, "rad", now);
        }

        if (Level == RunLevel.PedalDown && StaleArm() is { } stale)
        {
            MasterTimeout(stale.Arm, stale.AgeMs, now);
        }

        var driven = _robot.State == RobotState.Enabled;
        var homed = Level is RunLevel.PedalUp or RunLevel.PedalDown;
        for (var i = 0; i < _motors.Length; i++)
        {
            CheckMotor(i, driven, homed, now);
        }
    }

    /// <summary>The operator's pedals as the graph reports them (nothing when the graph has none): edges move the run level.</summary>
    private void FollowOperator()
    {
        var stop = _robot.EmergencyStopPedal;
        if (stop == OperatorPedal.Down && _lastEmergencyStop != OperatorPedal.Down && Level != RunLevel.EStop)
        {
            EmergencyStop(PedalSource, "emergency-stop pedal pressed");
        }

        _lastEmergencyStop = stop;
        var pedal = _robot.Pedal;
        if (pedal == OperatorPedal.Down && _lastPedal == OperatorPedal.Up && Level == RunLevel.PedalUp && StaleArm() is null)
        {
            PedalDown(PedalSource);
        }
        else if (pedal == OperatorPedal.Up && Level == RunLevel.PedalDown)
        {
            PedalUp(PedalSource, "pedal up: holding position");
        }

        _lastPedal = pedal;
    }

    /// <summary>The first arm whose input device data is older than the master timeout, with its age (ms), or null.</summary>
    private (int Arm, double AgeMs)? StaleArm()
    {
        for (var a = 0; a < _arms; a++)
        {
            var age = _robot.InputAgeMs(a);
            if (!(age <= Limits.MasterTimeoutMs))
            {
                return (a, age);
            }
        }

        return null;
    }

    /// <summary>
    /// The master timeout: with the safe state hold, the trip is recorded and the run level goes back to PEDAL_UP (the
    /// arms hold, teleoperation is ignored); with torque off, it is a trip like any other (E_STOP).
    /// </summary>
    private void MasterTimeout(int arm, double age, long now)
    {
        var joint = _robot.Definition.Arms[arm].Name;
        if (Limits.SafeStateOf(SafetyCheck.MasterTimeout) == SafeState.TorqueOff)
        {
            Trip(SafetyCheck.MasterTimeout, joint, age, Limits.MasterTimeoutMs, "ms", now);
            return;
        }

        lock (_tripGate)
        {
            if (!_tripped[(int)SafetyCheck.MasterTimeout])
            {
                _tripped[(int)SafetyCheck.MasterTimeout] = true;
                _trips.Add(new SafetyTrip(now, SafetyCheck.MasterTimeout, joint, age, Limits.MasterTimeoutMs, "ms", SafeState.Hold));
            }
        }

        PedalUp(TripSource, string.Create(CultureInfo.InvariantCulture, $"master_timeout {joint}: input data {age:0.#} ms old (limit {Limits.MasterTimeoutMs:0.#}): hold"));
    }

    private void CheckModules(long now)
    {
        for (var i = 0; i < _controllers.Length; i++)
        {
            var c = _controllers[i];
            if (c.MissedReplies == 0 || _answeredAt[i] == 0)
            {
                _answeredAt[i] = now;
            }
            else if (now - _answeredAt[i] > _silentTicks)
            {
                Trip(SafetyCheck.ModuleSilent, _controllerNames[i], Ms(now - _answeredAt[i]), Limits.ModuleSilentMs, "ms", now);
            }
        }
    }

    private void CheckMotor(int i, bool driven, bool homed, long now)
    {
        var m = _motors[i];
        var position = m.PositionRad;
        var current = m.CurrentA;
        if (!double.IsFinite(position) || !double.IsFinite(current))
        {
            Trip(SafetyCheck.NonFinite, _motorNames[i], double.IsFinite(position) ? current : position, 0, double.IsFinite(position) ? "A" : "rad", now);
            return;
        }

        var error = Math.Abs(_robot.SentGoalRad(m) - position);
        Persist(ref _trackingSince[i], driven && error > _trackingLimit[i], now, _trackingTicks, SafetyCheck.TrackingError, i, error, _trackingLimit[i], "rad");
        var limit = Limits.CurrentLimitFraction * m.CurrentLimitA;
        Persist(ref _currentSince[i], Math.Abs(current) > limit, now, _currentTicks, SafetyCheck.OverCurrent, i, Math.Abs(current), limit, "A");

        // Pot against encoder once the positions are trusted (after homing); the pot is read at the pot poll's rate.
        var pot = m.PotPositionRad;
        var distance = Math.Abs(pot - position);
        Persist(ref _potSince[i], homed && double.IsFinite(pot) && distance > _potLimit[i], now, _potTicks, SafetyCheck.PotMismatch, i, distance, _potLimit[i], "rad");
    }

    private void Persist(ref long since, bool beyond, long now, long allowed, SafetyCheck check, int motor, double measured, double limit, string unit)
    {
        if (!beyond)
        {
            since = 0;
            return;
        }

        if (since == 0)
        {
            since = now;
        }

        if (now - since >= allowed)
        {
            Trip(check, _motorNames[motor], measured, limit, unit, now);
        }
    }

    /// <summary>Records a trip (once per check until a reset), takes its safe state and moves to E-STOP.</summary>
    private void Trip(SafetyCheck check, string joint, double measured, double limit, string unit, long now, string source = TripSource, string? reason = null)
    {
        var action = Limits.SafeStateOf(check);
        lock (_tripGate)
        {
            if (_tripped[(int)check])
            {
                return;
            }

            _tripped[(int)check] = true;
            _trips.Add(new SafetyTrip(now, check, joint, measured, limit, unit, action));
        }

        _robot.HoldAtMeasured();
        if (action == SafeState.TorqueOff && !_torqueOffTaken)
        {
            _torqueOffTaken = true;
            TorqueOff();
        }

        if (Level != RunLevel.EStop)
        {
            _levels.MoveTo(RunLevel.EStop, source, reason ?? $"{check.Name()} {joint}".TrimEnd() + $": {action.Name()}");
        }
    }

    private void TorqueOff()
    {
        if (_robot.State is RobotState.Homing or RobotState.Disabled)
        {
            return;
        }

        try
        {
            _robot.EnableTorque(false);
        }
        catch (IOException)
        {
            // A module that does not answer cannot be told; its bus watchdog stops its motors when the goals stop.
        }
    }

    private double Ms(long ticks) => ticks * 1e3 / _time.TimestampFrequency;

    private static string ArmName(BusRobot robot, RobotController c) =>
        c.Definition.Arm >= 0 && c.Definition.Arm < robot.Definition.Arms.Count ? robot.Definition.Arms[c.Definition.Arm].Name : "?";
}
