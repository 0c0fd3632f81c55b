using RobotControl.Definitions.Model;

namespace RobotControl.Robot.Control;

/// <summary>
/// The robot as the control loop sees it: latest-value exchange with the bus, which runs elsewhere (its own thread,
/// or stepped by a simulation on a virtual clock). Every member is non-blocking and allocation-free, so the loop may
/// call them every tick. Joint values are radians in the arm's own (right-arm) model; arms are numbered as in the
/// robot file's <c>arms</c> list.
/// </summary>
public interface IRobotPort
{
    /// <summary>The robot's data file.</summary>
    RobotDefinition Definition { get; }

    /// <summary>Number of arms (as listed in the robot file).</summary>
    int ArmCount { get; }

    /// <summary>
    /// Publishes joint setpoints for one arm for the next bus cycle. Values are limited to the joint ranges; a
    /// non-finite value is never sent: that joint holds its last setpoint and a fault is raised.
    /// </summary>
    void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad);

    /// <summary>Publishes the tool jaw (open/close) setpoint of one arm, radians of jaw angle.</summary>
    void WriteJawSetpoint(int arm, double jawRad);

    /// <summary>Copies the latest joint positions the modules reported for one arm (through the inverse coupling).</summary>
    void ReadJointPositions(int arm, Span<double> jointsRad);

    /// <summary>Copies the latest filtered motor currents (A) of one arm, one per actuator in robot-file order.</summary>
    void ReadMotorCurrents(int arm, Span<double> currentsA);

    /// <summary>Current fault flags of the whole robot (zero when healthy).</summary>
    RobotFaults Faults { get; }

    /// <summary>Commands every motor to hold where it is (used when a plug-in faults or a value is invalid).</summary>
    void HoldPosition();
}

/// <summary>
/// The operator as the control loop reports it to a safety supervisor, straight, with no mailbox in the robot layer:
/// that the loop ticked (the loop's own deadline), how old each arm's input device data is (the master timeout) and how
/// fast the hand at the device moves (a jump), the teleoperation pedal and the emergency-stop pedal or button; and
/// whether teleoperation may drive the arms now. Called by the loop's thread every tick; every member is non-blocking
/// and allocation-free.
/// </summary>
public interface IOperatorPort
{
    /// <summary>
    /// True while teleoperation may drive the arms (a run level such as pedal down); false while the robot holds (a
    /// trip, pedal up, homing): the graph then zeroes the haptic handles' forces.
    /// </summary>
    bool TeleopAllowed { get; }

    /// <summary>The loop ticked (first thing each tick): a loop whose last tick is too old is behind (a deadline miss).</summary>
    void ReportTick();

    /// <summary>How old the input device data driving <paramref name="arm"/> is, ms (NaN: unknown, taken as too old).</summary>
    void ReportInputAge(int arm, double ageMs);

    /// <summary>
    /// The speed of the hand at the device driving <paramref name="arm"/>, mm/s before any scaling (a Touch's
    /// <c>speed_mm_s</c>); beyond what a hand can do it is a jump and the answer is false: the arm holds from this
    /// tick's setpoints on (teleoperation stops until the operator presses the pedal again).
    /// </summary>
    /// <returns>False when the sample is implausible: the caller publishes no setpoints this tick.</returns>
    bool ReportInputSpeed(int arm, double mmPerS);

    /// <summary>The teleoperation pedal (called every tick only when the graph wires one).</summary>
    void ReportPedal(bool down);

    /// <summary>Whether the emergency-stop pedal or button is pressed (called every tick only when the graph wires one).</summary>
    void ReportEmergencyStop(bool pressed);
}

/// <summary>Robot-level fault flags, surfaced in the graph as an output.</summary>
[Flags]
public enum RobotFaults
{
    /// <summary>Healthy.</summary>
    None = 0,

    /// <summary>A configured module does not answer.</summary>
    ModuleMissing = 1,

    /// <summary>A module reset (EMI, brown-out) and resumed from FRAM.</summary>
    ModuleReset = 2,

    /// <summary>A module reports a hardware error (over-current, Hall sequence, pot mismatch).</summary>
    HardwareError = 4,

    /// <summary>A module's bus watchdog tripped.</summary>
    WatchdogTripped = 8,

    /// <summary>A non-finite or out-of-range setpoint was rejected.</summary>
    SetpointRejected = 16,

    /// <summary>Bus errors (CRC, timeouts) exceed the retry budget.</summary>
    BusDegraded = 32,

    /// <summary>A motor is at its current limit.</summary>
    CurrentLimited = 64,
}
