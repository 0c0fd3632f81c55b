using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.States;
using RobotControl.Robot.Control.States;

namespace RobotControl.Host.Safety;

/// <summary>
/// The supervisor's homing, INIT -> HOMING -> PEDAL_UP, and the decision it rests on: which motors must be re-homed
/// from their pots. After an operator's reset every motor is, unless only silences caused the E-STOP and the pots
/// confirm every position (a stall past the modules' torque-off stage loses no position); otherwise only the motors
/// whose module says a position may be wrong. Owns that decision between a reset and the homing that follows it.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class SupervisedHoming
{
    private readonly BusRobot _robot;
    private readonly RobotController[] _controllers;
    private readonly MotorChecks _motors;
    private readonly StateMachine<RunLevel> _levels;
    private readonly ProtectionsAtArming _protections;
    private bool _mustRehome;
    private bool _confirmByPots;

    public SupervisedHoming(BusRobot robot, MotorChecks motors, StateMachine<RunLevel> levels)
    {
        _robot = robot;
        _controllers = [.. robot.Controllers];
        _motors = motors;
        _levels = levels;
        _protections = new ProtectionsAtArming(robot);
    }

    /// <summary>An operator's reset: every motor is re-homed next, unless <paramref name="silencesOnly"/> caused the E-STOP and no module says a position may be wrong (then the pots confirm them).</summary>
    public void AfterReset(bool silencesOnly)
    {
        _confirmByPots = silencesOnly && PositionsInDoubt() == 0;
        _mustRehome = !_confirmByPots;
    }

    /// <summary>
    /// From INIT: refused, with nothing moved, while a module has a protection switched off (<see cref="ProtectionsAtArming"/>); then motors off; the modules' bus holds acknowledged; re-homed from the pots and verified where positions
    /// may be lost; motors on, holding the measured positions, PEDAL_UP. Homing that does not verify every motor, or a
    /// module refusing the motors on, returns to INIT with its line.
    /// </summary>
    /// <exception cref="InvalidOperationException">At E_STOP (the message names its first trip), a module with a protection switched off (the message names module, motor, field and value; nothing moved), or homing incomplete (the message says how many motors failed and the first).</exception>
    /// <exception cref="IOException">A module refused (the message names it).</exception>
    /// <param name="source">Who asked.</param>
    /// <param name="stopCause">The trip that moved the run level to E_STOP (not the first listed: that may be a soft one, or one from before a reset).</param>
    public IReadOnlyList<HomingResult> Run(string source, SafetyTrip? stopCause)
    {
        if (_levels.Current == RunLevel.EStop)
        {
            var trip = stopCause;
            throw new InvalidOperationException(trip is null
                ? $"homing ({source}) refused: the run level is E_STOP; an operator reset comes first"
                : trip.Check == SafetyCheck.Operator
                ? $"homing ({source}) refused: E_STOP by an operator's emergency stop; an operator reset comes first"
                : string.Create(CultureInfo.InvariantCulture, $"homing ({source}) refused: E_STOP since the {trip.Check.Name()} trip {trip.Joint} ({trip.Measured:0.###} {trip.Unit}, limit {trip.Limit:0.###})").Replace("  ", " ", StringComparison.Ordinal) + "; an operator reset comes first");
        }

        if (_protections.FirstSwitchedOff() is { } off)
        {
            throw new InvalidOperationException($"homing ({source}) refused: {off}; the supervisor does not arm a module without its protections (write the robot file's values: robotctl params set --from-robot-file)");
        }

        _levels.MoveTo(RunLevel.Homing, source, "homing from the joint pots");
        try
        {
            return HomeAndEnable(source);
        }
        catch (IOException ex) when (_levels.Current == RunLevel.Homing) // an E-STOP meanwhile stays
        {
            _levels.MoveTo(RunLevel.Init, source, $"homing failed: {ex.Message}");
            throw;
        }
    }

    private IReadOnlyList<HomingResult> HomeAndEnable(string source)
    {
        _robot.HoldAtMeasured();
        if (_robot.ModulesHolding > 0)
        {
            _robot.AcknowledgeHoldsNow(); // homing is the operator's request for motion: the modules follow again, from where they hold
        }

        if (_robot.State is RobotState.Enabled or RobotState.Fault)
        {
            _robot.EnableTorque(false); // from a fault too (a module reset while the motors were off): homing needs the motors off
        }

        var byPots = _confirmByPots;
        _confirmByPots = false;
        var lost = _mustRehome ? _motors.Count : byPots ? Math.Max(PositionsInDoubt(), _motors.PotsNotConfirming()) : PositionsInDoubt();
        if (lost == 0)
        {
            MotorsOnHolding();
            _levels.MoveTo(RunLevel.PedalUp, source, byPots
                ? "after an E-STOP from a stall, the pots confirm every position: not re-homed; motors on, holding"
                : "no module reports a lost position or a pot mismatch: not re-homed; motors on, holding");
            return [];
        }

        var results = _robot.Home();
        var failed = results.Count(r => !r.Succeeded);
        if (failed > 0 || _robot.State != RobotState.Homed)
        {
            _levels.MoveTo(RunLevel.Init, source, $"homing incomplete: {failed} of {results.Count} motors not homed");
            var first = results.First(r => !r.Succeeded);
            throw new InvalidOperationException($"homing incomplete: {failed} of {results.Count} motors not homed (first: {first.Motor.Config.FullName} {first.Outcome}{(first.Detail.Length > 0 ? ": " + first.Detail : string.Empty)}); the run level stays INIT");
        }

        _mustRehome = false;
        MotorsOnHolding();
        _levels.MoveTo(RunLevel.PedalUp, source, $"{results.Count} motors homed and verified ({(lost == _motors.Count ? "after a reset" : $"{lost} had lost their position")}); motors on, holding");
        return results;
    }

    /// <summary>
    /// Motors on, holding the positions measured now. The hold is asked afresh: the robot has held since before homing
    /// (at INIT it always holds), at positions that homing (or a joint turned while off) may have changed since, and
    /// holding those would drive the motors back to them.
    /// </summary>
    private void MotorsOnHolding()
    {
        _robot.ReleaseHold();
        _robot.HoldAtMeasured();
        _robot.EnableTorque(true);
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
}
