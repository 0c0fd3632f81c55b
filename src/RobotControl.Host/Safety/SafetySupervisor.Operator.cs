using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.States;

namespace RobotControl.Host.Safety;

/// <summary>
/// The operator's commands: home, pedal down and up, motors off, reset, each run on the bus thread between cycles
/// (called from another thread while a bus thread runs, the call waits for it); and the emergency stop, which never
/// waits.
/// </summary>
public sealed partial class SafetySupervisor
{
    /// <summary>INIT -> HOMING -> PEDAL_UP, re-homing from the pots where positions may be lost (<see cref="SupervisedHoming"/>); back to INIT when it cannot.</summary>
    /// <exception cref="InvalidOperationException">Not at INIT, or homing incomplete (the message says how many motors failed).</exception>
    /// <exception cref="IOException">A module refused the motors on (the message names it).</exception>
    public IReadOnlyList<HomingResult> Home(string source) => _robot.Slot.Run($"homing ({source})", () =>
    {
        var results = _homing.Run(source, _stopCause); // refused at E_STOP naming the trip that caused it
        _torqueOffTaken = false;
        return results;
    });

    /// <summary>PEDAL_UP -> PEDAL_DOWN: teleoperation drives the arms (from the measured positions, under the step cap).</summary>
    /// <exception cref="InvalidOperationException">Not at PEDAL_UP, or an arm's input device data is older than the master timeout.</exception>
    public void PedalDown(string source) => _robot.Slot.Run($"pedal down ({source})", () => PedalDownOnBus(source));

    private void PedalDownOnBus(string source)
    {
        if (!_levels.CanMoveTo(RunLevel.PedalDown))
        {
            throw new InvalidOperationException($"pedal down ({source}) needs the run level PEDAL_UP, it is {Level.Name()}");
        }

        if (StaleArm() is { } stale)
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"pedal down ({source}) refused: the input data of the {_robot.Definition.Arms[stale.Arm].Name} arm is {stale.AgeMs:0.#} ms old (master_timeout_ms {Limits.MasterTimeoutMs:0.#})"));
        }

        var now = _time.GetTimestamp();
        if (_clock.LoopLag(now) is var lag && lag > _clock.StallTicks)
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"pedal down ({source}) refused: the control loop has not ticked for {_clock.Ms(lag):0} ms"));
        }

        if (_moduleChecks.Silent(now) is { } silent)
        {
            throw new InvalidOperationException(string.Create(CultureInfo.InvariantCulture, $"pedal down ({source}) refused: module {silent.Module} has not answered for {silent.Ms:0.#} ms (module_silent_ms {Limits.ModuleSilentMs:0.#})"));
        }

        _trips.NewEpisode(); // a new episode of teleoperation: a new timeout, jump or silence is a new trip

        if (_robot.ModulesHolding > 0)
        {
            _robot.RequestHoldAcknowledgement(); // at the next write, before its goals: the modules follow again from where they held
        }

        _robot.ReleaseHold();
        _levels.MoveTo(RunLevel.PedalDown, source, "pedal down: teleoperation drives the arms");
    }

    /// <summary>PEDAL_DOWN -> PEDAL_UP: the arms hold where they are; teleoperation is ignored.</summary>
    public void PedalUp(string source, string reason = "pedal up: holding position") => _robot.Slot.Run($"pedal up ({source})", () => PedalUpOnBus(source, reason));

    private void PedalUpOnBus(string source, string reason)
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
        _robot.Slot.Run($"motors off ({source})", () => MotorsOffOnBus(source));
    }

    private void MotorsOffOnBus(string source)
    {
        if (Level == RunLevel.Homing)
        {
            throw new InvalidOperationException($"motors off ({source}): homing runs, wait for it to end");
        }

        PedalUpOnBus(source, "pedal up: the motors go off");
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

    /// <summary>
    /// An emergency stop, from any source and any thread (a console, watching or operating; the command line; a
    /// signal), lock-free and never waiting: the robot holds (and, when the operator check's safe state says so, its
    /// motors go off) at the next write, ahead of any queued work, whose running piece is cut short at its next
    /// transaction; the trip is recorded and the run level moves to E_STOP at the next check (at once when called on
    /// the bus thread itself: a command between cycles, the pedal in a check).
    /// </summary>
    public void EmergencyStop(string source, string reason)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(source);
        ArgumentException.ThrowIfNullOrWhiteSpace(reason);
        _robot.EmergencyHold(reason, _grading.SafeStateOf(SafetyCheck.Operator) == SafeState.TorqueOff && !_torqueOffTaken);
        if (_robot.Slot.IsOwner)
        {
            Trip(SafetyCheck.Operator, string.Empty, 0, 0, string.Empty, _time.GetTimestamp(), source, reason);
            return;
        }

        Volatile.Write(ref _stopRequest, new EmergencyStopRequest(source, reason));
    }

    /// <summary>
    /// Leaves E-STOP for INIT, on an operator's explicit request: motors off, faults cleared. The robot must be homed
    /// again (<see cref="Home"/>) before it may move: positions may have been lost.
    /// </summary>
    /// <exception cref="InvalidOperationException">Not at E-STOP.</exception>
    public void Reset(string source) => _robot.Slot.Run($"reset ({source})", () => ResetOnBus(source));

    private void ResetOnBus(string source)
    {
        if (Level != RunLevel.EStop)
        {
            throw new InvalidOperationException($"reset ({source}) applies at E_STOP only, the run level is {Level.Name()}");
        }

        if (_robot.State is RobotState.Enabled or RobotState.Fault)
        {
            _robot.EnableTorque(false);
        }

        // After an E-STOP that only silences caused (a host stall past the modules' torque-off stage, the modules' own
        // watchdog), with no module reporting a lost position, the pots may confirm the positions instead of homing.
        _homing.AfterReset(silencesOnly: Trips.Where(t => !t.Soft).All(t => t.Check.IsSilence() || t.Check == SafetyCheck.ModuleFault));
        _robot.ClearFaultsNow(); // before anything else may ask for motors on
        _trips.Reset();

        _motorChecks.Clear();
        _levels.MoveTo(RunLevel.Init, source, "operator reset: motors off, faults cleared; homing needed before motion");
    }

    /// <summary>The operator's pedals as the graph reports them (nothing when the graph has none): edges move the run level.</summary>
    private void FollowOperator()
    {
        if (Volatile.Read(ref _stopRequest) is not null && Interlocked.Exchange(ref _stopRequest, null) is { } request)
        {
            Trip(SafetyCheck.Operator, string.Empty, 0, 0, string.Empty, _time.GetTimestamp(), request.Source, request.Reason);
        }

        var stop = _inputs.EmergencyStop;
        if (stop == OperatorPedal.Down && _lastEmergencyStop != OperatorPedal.Down && Level != RunLevel.EStop)
        {
            EmergencyStop(PedalSource, "emergency-stop pedal pressed");
        }

        _lastEmergencyStop = stop;
        var pedal = _inputs.Pedal;
        if (pedal == OperatorPedal.Down && _lastPedal == OperatorPedal.Up && Level == RunLevel.PedalUp && StaleArm() is null)
        {
            PedalDownOnBus(PedalSource);
        }
        else if (pedal == OperatorPedal.Up && Level == RunLevel.PedalDown)
        {
            PedalUpOnBus(PedalSource, "pedal up: holding position");
        }

        _lastPedal = pedal;
    }

    /// <summary>
    /// True while the robot follows the setpoints and the bus cycles on time. From a tick whose bus cycle is late (a
    /// stall the bus thread has not seen yet) it is false, so that the graph's clutch holds the master's target from
    /// before the stall and re-engaging starts where the arms hold.
    /// </summary>
    public bool TeleopAllowed => !_robot.IsHolding && _clock.OnTime();

    /// <inheritdoc />
    public void ReportTick() => _inputs.ReportTick();

    /// <inheritdoc />
    public void ReportInputAge(int arm, double ageMs) => _inputs.ReportAge(arm, ageMs);

    /// <inheritdoc />
    public bool ReportInputSpeed(int arm, double mmPerS) => _inputs.ReportSpeed(arm, mmPerS);

    /// <inheritdoc />
    public void ReportPedal(bool down) => _inputs.ReportPedal(down);

    /// <inheritdoc />
    public void ReportEmergencyStop(bool pressed) => _inputs.ReportEmergencyStop(pressed);
}
