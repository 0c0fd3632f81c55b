namespace RobotControl.Bus.Protocol;

/// <summary>
/// The error number in the low 7 bits of a status packet's error byte, as Dynamixel Protocol 2.0 defines it
/// (docs/protocol.md says when a module sends each one). Bit 7 is the alert flag, not part of the number.
/// </summary>
public enum StatusError : byte
{
    /// <summary>No error.</summary>
    None = 0x00,

    /// <summary>The instruction could not be carried out (e.g. torque refused while the watchdog error is latched).</summary>
    ResultFail = 0x01,

    /// <summary>Undefined instruction, or ACTION without a registered write.</summary>
    Instruction = 0x02,

    /// <summary>CRC mismatch (the modules drop such frames instead of answering).</summary>
    Crc = 0x03,

    /// <summary>A value outside the field's range (min..max of the control table).</summary>
    DataRange = 0x04,

    /// <summary>Too few parameters, or a write shorter than the field it touches.</summary>
    DataLength = 0x05,

    /// <summary>A value beyond a configured limit (a goal outside position_min..position_max).</summary>
    DataLimit = 0x06,

    /// <summary>Unmapped, read-only or write-only bytes, or a persistent-area write while torque is on.</summary>
    Access = 0x07,
}

/// <summary>Reading a status error byte.</summary>
public static class StatusErrors
{
    /// <summary>Mask of the error number; bit 7 is the alert flag.</summary>
    public const byte NumberMask = 0x7F;

    /// <summary>The error number of <paramref name="errorByte"/> (alert bit removed).</summary>
    public static StatusError Number(byte errorByte) => (StatusError)(errorByte & NumberMask);

    /// <summary>A short text for logs and messages, e.g. "0x07 access error (alert)".</summary>
    public static string Describe(byte errorByte)
    {
        var name = Number(errorByte) switch
        {
            StatusError.None => "no error",
            StatusError.ResultFail => "result fail",
            StatusError.Instruction => "instruction error",
            StatusError.Crc => "CRC error",
            StatusError.DataRange => "data range error",
            StatusError.DataLength => "data length error",
            StatusError.DataLimit => "data limit error",
            StatusError.Access => "access error",
            _ => "unknown error",
        };
        return $"0x{errorByte & NumberMask:X2} {name}{((errorByte & 0x80) != 0 ? " (alert)" : string.Empty)}";
    }
}
