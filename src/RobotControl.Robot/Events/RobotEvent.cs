using RobotControl.Robot.Bus;

namespace RobotControl.Robot.Events;

/// <summary>
/// Something that happened to the robot on its bus (a module missing, reset or back; a watchdog; a bus error), in
/// <see cref="Bus.BusRobot.Events"/>, oldest first. Typed so that readers select by kind, never by text; the
/// <see cref="Message"/> is the one line a person reads (the run report's fault text).
/// </summary>
public abstract record RobotEvent
{
    /// <summary>The line a person reads.</summary>
    public abstract string Message { get; }

    /// <inheritdoc />
    public sealed override string ToString() => Message;
}

/// <summary>Discovery found a configured module missing or not as configured, or a module the robot file does not list.</summary>
/// <param name="Problem">The finding.</param>
public sealed record DiscoveryProblemEvent(DiscoveryProblem Problem) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => Problem.Line;
}

/// <summary>A present module missed enough cycles in a row to count as missing.</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
public sealed record ModuleStoppedAnswering(byte ModuleId, string Name) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\" stopped answering";
}

/// <summary>A missing module answers again and takes part in the cycles.</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
public sealed record ModuleAnswersAgain(byte ModuleId, string Name) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\" answers again";
}

/// <summary>A module reset while the host was connected.</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
/// <param name="Cause">The reset cause's name (the control table's <c>reset_cause</c> codes).</param>
/// <param name="ResumedFromFram">True when it resumed its position record; false when it homed from its pot.</param>
/// <param name="PotMismatch">True when its position disagrees with the pot (its motors are left off).</param>
public sealed record ModuleResetEvent(byte ModuleId, string Name, string Cause, bool ResumedFromFram, bool PotMismatch) : RobotEvent
{
    /// <inheritdoc />
    public override string Message =>
        $"module {ModuleId} \"{Name}\" reset ({Cause}); " +
        (ResumedFromFram ? "resumed its position from FRAM" : "had no position record and homed from its pot") +
        (PotMismatch ? "; its position disagrees with the pot: motors left off" : string.Empty);
}

/// <summary>A module's bus watchdog stopped its motors (the host fell silent too long).</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
public sealed record WatchdogTripped(byte ModuleId, string Name) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\": bus watchdog tripped, motors stopped";
}

/// <summary>A module holds its motors where they were: no frame reached it for its bus watchdog's first stage.</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
public sealed record ModuleHolding(byte ModuleId, string Name) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\": bus silent for its watchdog's first stage, holding its motors; goals refused until the hold is acknowledged";
}

/// <summary>The host acknowledged a module's bus hold: it follows the goals again.</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
public sealed record HoldAcknowledged(byte ModuleId, string Name) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\": hold acknowledged, following the goals again";
}

/// <summary>A module latched a hardware error (Hall sequence, pot mismatch).</summary>
/// <param name="ModuleId">Its bus ID.</param>
/// <param name="Name">Its name in the robot file.</param>
/// <param name="Errors">Its error bits.</param>
public sealed record HardwareErrorLatched(byte ModuleId, string Name, RobotControl.Modules.HardwareErrors Errors) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"module {ModuleId} \"{Name}\": hardware error {Errors}";
}

/// <summary>A bus cycle failed on the link (the bus thread goes on after a short pause).</summary>
/// <param name="Detail">What the link said.</param>
public sealed record BusError(string Detail) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => $"bus error: {Detail}";
}

/// <summary>A module refused to turn its motors on again after faults were cleared.</summary>
/// <param name="Detail">What it refused and why.</param>
public sealed record TorqueRefused(string Detail) : RobotEvent
{
    /// <inheritdoc />
    public override string Message => Detail;
}
