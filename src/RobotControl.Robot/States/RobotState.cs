namespace RobotControl.Robot.States;

/// <summary>Where a robot on its bus is in its life (see <see cref="RobotStateMachine"/> for the moves between them).</summary>
public enum RobotState
{
    /// <summary>Opened, nothing known about the bus yet: discover first.</summary>
    Disabled,

    /// <summary>The bus was searched; present modules take part in the cycles; motors off.</summary>
    Discovered,

    /// <summary>Motors are being homed from their pots (motors off).</summary>
    Homing,

    /// <summary>Every present motor was homed and verified; motors off.</summary>
    Homed,

    /// <summary>Motors on, following the setpoints (bus watchdogs armed).</summary>
    Enabled,

    /// <summary>A module stopped its motors (watchdog) or latched a hardware error: clear faults, or turn the motors off.</summary>
    Fault,
}

/// <summary>One move of the robot's state, as recorded.</summary>
/// <param name="At">When, on the robot's clock, since the robot was opened.</param>
/// <param name="From">The state left.</param>
/// <param name="To">The state entered.</param>
/// <param name="Reason">Why.</param>
public sealed record RobotTransition(TimeSpan At, RobotState From, RobotState To, string Reason)
{
    /// <inheritdoc />
    public override string ToString() => $"{At.TotalSeconds:F3} s: {From} -> {To} ({Reason})";
}
