namespace RobotControl.Definitions.Model;

/// <summary>The per-cycle checks of the safety supervisor.</summary>
public enum SafetyCheck
{
    /// <summary>A position, current or setpoint is NaN or infinite (a setpoint refused by the robot layer included).</summary>
    NonFinite,

    /// <summary>A module has not answered for longer than its limit.</summary>
    ModuleSilent,

    /// <summary>|goal sent − measured position| beyond the limit for longer than the time.</summary>
    TrackingError,

    /// <summary>A motor's current over its limit for longer than the time.</summary>
    OverCurrent,

    /// <summary>|joint pot position − encoder (Hall) position| beyond the limit for longer than the time.</summary>
    PotMismatch,

    /// <summary>
    /// The control loop fell behind: its last tick is k loop periods old or more (a tick that overran or hangs, a loop
    /// thread that was not scheduled). Graded as <see cref="HostStall"/>.
    /// </summary>
    DeadlineMiss,

    /// <summary>The robot layer reports a module fault (firmware watchdog, hardware error).</summary>
    ModuleFault,

    /// <summary>An operator (console, CLI or pedal) asked for an emergency stop.</summary>
    Operator,

    /// <summary>The input device data driving an arm is older than the limit (the master timeout): back to PEDAL_UP when its safe state is hold.</summary>
    MasterTimeout,

    /// <summary>While the motors are on, a module's bus watchdog (read back) is off or not the robot file's period.</summary>
    WatchdogUnarmed,

    /// <summary>
    /// The host stalled: a gap of k loop periods or more between two bus cycles. Graded: shorter than the modules'
    /// torque-off stage (their second watchdog stage) it is a soft trip, the arms hold and the run level goes back to
    /// PEDAL_UP; from that stage on the modules have switched their motors off, and it is E_STOP.
    /// </summary>
    HostStall,

    /// <summary>A master sample implies a hand speed no hand can produce (a jump): a soft trip, hold and PEDAL_UP, as the master timeout.</summary>
    MasterJump,

    /// <summary>
    /// A plug-in upstream of the robot faulted (its tick or start threw): it is no longer ticked, the robot node holds
    /// the arms, and the trip names the plug-in and what it threw.
    /// </summary>
    PluginFault,
}

/// <summary>What the robot does after a trip.</summary>
public enum SafeState
{
    /// <summary>Goals frozen at the measured positions; motors stay on.</summary>
    Hold,

    /// <summary>Motors off (the modules' bridges disabled).</summary>
    TorqueOff,
}

/// <summary>Kinds of checks.</summary>
public static class SafetyCheckKinds
{
    /// <summary>
    /// True for the checks that time a silence (the host's, the loop's, a module's): graded against the modules'
    /// torque-off stage, and counted apart from the loop's deadline misses.
    /// </summary>
    public static bool IsSilence(this SafetyCheck check) => check is SafetyCheck.HostStall or SafetyCheck.DeadlineMiss or SafetyCheck.ModuleSilent;
}

/// <summary>Report names of checks and safe states.</summary>
public static class SafetyNames
{
    /// <summary>The check's name in the robot file and the report, e.g. <c>tracking_error</c>.</summary>
    public static string Name(this SafetyCheck check) => check switch
    {
        SafetyCheck.NonFinite => "non_finite",
        SafetyCheck.ModuleSilent => "module_silent",
        SafetyCheck.TrackingError => "tracking_error",
        SafetyCheck.OverCurrent => "over_current",
        SafetyCheck.PotMismatch => "pot_mismatch",
        SafetyCheck.DeadlineMiss => "deadline_miss",
        SafetyCheck.ModuleFault => "module_fault",
        SafetyCheck.Operator => "operator",
        SafetyCheck.MasterTimeout => "master_timeout",
        SafetyCheck.WatchdogUnarmed => "watchdog_unarmed",
        SafetyCheck.HostStall => "host_stall",
        SafetyCheck.MasterJump => "master_jump",
        SafetyCheck.PluginFault => "plugin_fault",
        _ => check.ToString(),
    };

    /// <summary><c>hold</c> or <c>torque_off</c>.</summary>
    public static string Name(this SafeState state) => state == SafeState.Hold ? "hold" : "torque_off";
}
