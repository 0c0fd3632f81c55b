namespace RobotControl.Robot.Bus;

/// <summary>
/// Bits of the control table's <c>hardware_error_status</c> (firmware/protocol/control-table.json); a motor's
/// <c>motor_error</c> uses the same bits for its own over-current, Hall, pot-mismatch and position-lost errors.
/// </summary>
[Flags]
public enum HardwareErrors : byte
{
    /// <summary>No latched error.</summary>
    None = 0,

    /// <summary>A motor hit its current limit hard enough to latch.</summary>
    OverCurrent = 0x01,

    /// <summary>Invalid or skipped Hall states.</summary>
    Hall = 0x02,

    /// <summary>After a reset, the restored position disagrees with the pot (cleared by homing the motor).</summary>
    PotMismatch = 0x04,

    /// <summary>The bus watchdog stopped the motors.</summary>
    BusWatchdog = 0x08,

    /// <summary>FRAM parameters were invalid; defaults were loaded.</summary>
    ParametersLost = 0x10,

    /// <summary>
    /// No position record survived a reset: the position was taken from the pot (0 if uncalibrated) and the motor has
    /// not been homed since.
    /// </summary>
    PositionLost = 0x20,
}
