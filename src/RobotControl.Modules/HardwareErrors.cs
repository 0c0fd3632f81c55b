using RobotControl.Bus.Protocol;

namespace RobotControl.Modules;

/// <summary>
/// Bits of the control table's <c>hardware_error_status</c>; a motor's <c>motor_error</c> uses the same bits for its
/// own over-current, Hall, pot-mismatch and position-lost errors. The bit positions and names come from the field's
/// <c>bits</c> in firmware/protocol/control-table.json (the firmware's source too); nothing here repeats a number.
/// </summary>
/// <param name="Value">The raw bits.</param>
public readonly record struct HardwareErrors(byte Value)
{
    private const string Field = "hardware_error_status";

    /// <summary>No latched error.</summary>
    public static HardwareErrors None => default;

    /// <summary>A motor hit its current limit hard enough to latch.</summary>
    public static HardwareErrors OverCurrent { get; } = Named("over_current");

    /// <summary>Invalid or skipped Hall states.</summary>
    public static HardwareErrors Hall { get; } = Named("hall");

    /// <summary>After a reset, the restored position disagrees with the pot (cleared by homing the motor).</summary>
    public static HardwareErrors PotMismatch { get; } = Named("pot_mismatch");

    /// <summary>The bus watchdog stopped the motors (its stage 2: no frame for <c>bus_watchdog_off</c> ms).</summary>
    public static HardwareErrors BusWatchdog { get; } = Named("bus_watchdog");

    /// <summary>
    /// The bus watchdog's stage 1 (no frame for <c>bus_watchdog</c> ms): the module holds every motor where it was and
    /// refuses goals and torque-on until the host clears this bit (its acknowledgement of the hold).
    /// </summary>
    public static HardwareErrors BusHold { get; } = Named("bus_hold");

    /// <summary>FRAM parameters were invalid; defaults were loaded.</summary>
    public static HardwareErrors ParametersLost { get; } = Named("parameters_lost");

    /// <summary>
    /// No position record survived a reset: the position was taken from the pot (0 if uncalibrated) and the motor has
    /// not been homed since.
    /// </summary>
    public static HardwareErrors PositionLost { get; } = Named("position_lost");

    /// <summary>True when no bit is set.</summary>
    public bool IsNone => Value == 0;

    /// <summary>The bits of <paramref name="value"/> (e.g. a register read).</summary>
    public static explicit operator HardwareErrors(long value) => new((byte)value);

    /// <summary>The raw bits.</summary>
    public static explicit operator byte(HardwareErrors errors) => errors.Value;

    /// <summary>Either's bits.</summary>
    public static HardwareErrors operator |(HardwareErrors a, HardwareErrors b) => new((byte)(a.Value | b.Value));

    /// <summary>Both's bits.</summary>
    public static HardwareErrors operator &(HardwareErrors a, HardwareErrors b) => new((byte)(a.Value & b.Value));

    /// <summary>Every other bit.</summary>
    public static HardwareErrors operator ~(HardwareErrors a) => new((byte)~a.Value);

    /// <summary>Either's bits (named form of <c>|</c>).</summary>
    public static HardwareErrors BitwiseOr(HardwareErrors a, HardwareErrors b) => a | b;

    /// <summary>Both's bits (named form of <c>&amp;</c>).</summary>
    public static HardwareErrors BitwiseAnd(HardwareErrors a, HardwareErrors b) => a & b;

    /// <summary>Every other bit (named form of <c>~</c>).</summary>
    public static HardwareErrors OnesComplement(HardwareErrors a) => ~a;

    /// <summary>The raw bits.</summary>
    public byte ToByte() => Value;

    /// <summary>The bits of <paramref name="value"/> (named form of the explicit conversion).</summary>
    public static HardwareErrors FromInt64(long value) => new((byte)value);

    /// <summary>True when every bit of <paramref name="flags"/> is set.</summary>
    public bool HasFlag(HardwareErrors flags) => (Value & flags.Value) == flags.Value;

    /// <summary>True when any bit of <paramref name="flags"/> is set.</summary>
    public bool HasAny(HardwareErrors flags) => (Value & flags.Value) != 0;

    /// <summary>The set bits by their control-table names, e.g. <c>hall, pot_mismatch</c> (<c>none</c> when clear).</summary>
    public override string ToString()
    {
        if (Value == 0)
        {
            return "none";
        }

        var names = new List<string>();
        for (var bit = 0; bit < 8; bit++)
        {
            if ((Value & (1 << bit)) != 0)
            {
                names.Add(ControlTable.Firmware.Bits(Field).FirstOrDefault(b => b.Value == bit).Key ?? $"bit{bit}");
            }
        }

        return string.Join(", ", names);
    }

    private static HardwareErrors Named(string name) => new((byte)ControlTable.Firmware.Bit(Field, name));
}
