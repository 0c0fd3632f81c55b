namespace RobotControl.Robot.States;

/// <summary>Where a robot on its bus is in its life (the moves between them are declared in <c>RobotLifecycle</c>).</summary>
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
