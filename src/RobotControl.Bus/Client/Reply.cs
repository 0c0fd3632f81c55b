namespace RobotControl.Bus.Client;

/// <summary>How a request ended.</summary>
public enum ReplyOutcome
{
    /// <summary>The module answered (check <see cref="Reply.Error"/>).</summary>
    Ok,

    /// <summary>No valid answer within the timeout, after every retry.</summary>
    Timeout,

    /// <summary>The answer was shorter or longer than requested.</summary>
    BadLength,
}

/// <summary>Result of one request: outcome and the status packet's error byte.</summary>
/// <param name="Outcome">How the request ended.</param>
/// <param name="Error">The error byte of the module's status packet (0: none).</param>
public readonly record struct Reply(ReplyOutcome Outcome, byte Error)
{
    /// <summary>True when the module answered without an error flag in the low 7 bits (bit 7 is the alert flag).</summary>
    public bool Succeeded => Outcome == ReplyOutcome.Ok && (Error & 0x7F) == 0;

    /// <summary>True when the status packet's alert bit (hardware error latched) is set.</summary>
    public bool Alert => (Error & 0x80) != 0;

    /// <summary>A timeout.</summary>
    public static Reply TimedOut => new(ReplyOutcome.Timeout, 0);
}

/// <summary>A module found by ping.</summary>
/// <param name="Id">Its bus ID.</param>
/// <param name="ModelNumber">Control-table model number.</param>
/// <param name="FirmwareVersion">Firmware version byte.</param>
public readonly record struct PingInfo(byte Id, ushort ModelNumber, byte FirmwareVersion);
