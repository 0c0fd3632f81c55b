namespace RobotControl.WebConsole.Session;

/// <summary>How a command ended.</summary>
public enum CommandOutcome
{
    /// <summary>Applied.</summary>
    Ok,

    /// <summary>The request was malformed or a value out of range; nothing was applied.</summary>
    BadInput,

    /// <summary>No such motor, controller or parameter; nothing was applied.</summary>
    NotFound,

    /// <summary>The robot or a module refused (its error is in the message); nothing was applied.</summary>
    Refused,

    /// <summary>The command could not be carried out (no reply, session stopping).</summary>
    Failed,
}

/// <summary>The result of a command: its outcome, one line saying what happened, and optional details (one per motor).</summary>
/// <param name="Outcome">How it ended.</param>
/// <param name="Message">One line for the operator.</param>
/// <param name="Details">Further lines (e.g. homing results per motor).</param>
public sealed record CommandResult(CommandOutcome Outcome, string Message, IReadOnlyList<string> Details)
{
    /// <summary>True when applied.</summary>
    public bool Succeeded => Outcome == CommandOutcome.Ok;

    /// <summary>An applied command.</summary>
    public static CommandResult Ok(string message, IReadOnlyList<string>? details = null) => new(CommandOutcome.Ok, message, details ?? []);

    /// <summary>A refused command.</summary>
    public static CommandResult Fail(CommandOutcome outcome, string message, IReadOnlyList<string>? details = null) => new(outcome, message, details ?? []);
}
