namespace RobotControl.Definitions.Model;

/// <summary>
/// Thresholds of the safety supervisor's checks and the safe state of each: the robot file's optional <c>safety</c>
/// section, read and validated by the robot loader (<see cref="RobotDefinition.Safety"/>); every field has a default.
/// </summary>
public sealed record SafetyLimits
{
    /// <summary>Largest |goal sent − measured position| of a motor, output radians (default 0.35 rad, 20°).</summary>
    public double TrackingErrorRad { get; init; } = 0.35;

    /// <summary>How long the tracking error may stay beyond its limit, ms (default 50).</summary>
    public double TrackingErrorMs { get; init; } = 50;

    /// <summary>Current limit as a fraction of each motor's <c>current_limit</c> in the robot file (default 0.95).</summary>
    public double CurrentLimitFraction { get; init; } = 0.95;

    /// <summary>How long the current may stay over its limit, ms (default 50, as the dVRK's current check).</summary>
    public double OverCurrentMs { get; init; } = 50;

    /// <summary>Largest |pot position − encoder position| of a motor, output radians (default 0.087 rad, 5°, as the dVRK's check).</summary>
    public double PotDistanceRad { get; init; } = 5 * Math.PI / 180;

    /// <summary>How long the pot and the encoder may disagree, ms (default 10, as the dVRK's check).</summary>
    public double PotMismatchMs { get; init; } = 10;

    /// <summary>How long a module may stay silent, ms (default 10); graded as a host stall (<see cref="SafetyCheck.HostStall"/>).</summary>
    public double ModuleSilentMs { get; init; } = 10;

    /// <summary>Loop periods without a bus cycle (a host stall) or without a loop tick (deadline misses) that count as a stall (default 10).</summary>
    public int DeadlineMissesInARow { get; init; } = 10;

    /// <summary>How old the input device data driving an arm may be while teleoperation drives it, ms (default 50: the master timeout).</summary>
    public double MasterTimeoutMs { get; init; } = 50;

    /// <summary>
    /// The fastest the hand at a master device may move, mm/s at the device, before any scaling (default 2,000: a hand
    /// does not exceed 2 m/s); a sample implying more is a jump (<see cref="SafetyCheck.MasterJump"/>).
    /// </summary>
    public double MasterSpeedMaxMmPerS { get; init; } = 2000;

    /// <summary>Longest bus watchdog period the robot file's <c>modules.watchdog_ms</c> may set, ms (default 30, as the dVRK's hardware watchdog).</summary>
    public double BusWatchdogMaxMs { get; init; } = 30;

    /// <summary>
    /// Longest a module may hold its motors on its own after the host falls silent before it switches them off: the
    /// bound of the robot file's <c>modules.watchdog_off_ms</c>, ms (default 1000).
    /// </summary>
    public double BusWatchdogOffMaxMs { get; init; } = 1000;

    /// <summary>Per-motor thresholds that override the robot-wide ones, by motor name (<c>arm.motor</c>, e.g. <c>right.elbow</c>).</summary>
    public IReadOnlyDictionary<string, MotorSafetyLimits> Motors { get; init; } = new Dictionary<string, MotorSafetyLimits>();

    /// <summary>The tracking-error limit of motor <paramref name="motor"/> (its own, else <see cref="TrackingErrorRad"/>).</summary>
    public double TrackingErrorRadOf(string motor) => Motors.TryGetValue(motor, out var m) && m.TrackingErrorRad is { } v ? v : TrackingErrorRad;

    /// <summary>The pot/encoder distance limit of motor <paramref name="motor"/> (its own, else <see cref="PotDistanceRad"/>).</summary>
    public double PotDistanceRadOf(string motor) => Motors.TryGetValue(motor, out var m) && m.PotDistanceRad is { } v ? v : PotDistanceRad;

    /// <summary>
    /// Safe state per check. Defaults: hold for the soft trips (a host stall, a loop behind, a silent module, each
    /// shorter than the modules' torque-off stage; the master timeout and a master jump), which go back to PEDAL_UP
    /// instead of E_STOP, and for a non-finite value, a tracking error and the operator's stop; torque off for
    /// over-current, a pot/encoder mismatch, module faults and an unarmed bus watchdog.
    /// </summary>
    public IReadOnlyDictionary<SafetyCheck, SafeState> SafeStates { get; init; } = DefaultSafeStates;

    /// <summary>The defaults of <see cref="SafeStates"/>.</summary>
    public static IReadOnlyDictionary<SafetyCheck, SafeState> DefaultSafeStates { get; } = new Dictionary<SafetyCheck, SafeState>
    {
        [SafetyCheck.NonFinite] = SafeState.Hold,
        [SafetyCheck.ModuleSilent] = SafeState.Hold,
        [SafetyCheck.TrackingError] = SafeState.Hold,
        [SafetyCheck.OverCurrent] = SafeState.TorqueOff,
        [SafetyCheck.PotMismatch] = SafeState.TorqueOff,
        [SafetyCheck.DeadlineMiss] = SafeState.Hold,
        [SafetyCheck.ModuleFault] = SafeState.TorqueOff,
        [SafetyCheck.Operator] = SafeState.Hold,
        [SafetyCheck.MasterTimeout] = SafeState.Hold,
        [SafetyCheck.WatchdogUnarmed] = SafeState.TorqueOff,
        [SafetyCheck.HostStall] = SafeState.Hold,
        [SafetyCheck.MasterJump] = SafeState.Hold,
        [SafetyCheck.PluginFault] = SafeState.Hold,
    };

    /// <summary>The safe state of <paramref name="check"/>.</summary>
    public SafeState SafeStateOf(SafetyCheck check) => SafeStates.TryGetValue(check, out var s) ? s : DefaultSafeStates[check];
}

/// <summary>A motor's own thresholds (null: the robot-wide one).</summary>
/// <param name="TrackingErrorRad">Largest |goal sent − measured position|, output radians.</param>
/// <param name="PotDistanceRad">Largest |pot position − encoder position|, output radians.</param>
public sealed record MotorSafetyLimits(double? TrackingErrorRad, double? PotDistanceRad);
