namespace RobotControl.Robot.Bus;

/// <summary>How a <see cref="BusRobot"/> runs its bus.</summary>
public sealed record BusRobotOptions
{
    /// <summary>Read every module's error status and reset cause every this many cycles (resets raise no alert).</summary>
    public int StatusPollCycles { get; init; } = 8;

    /// <summary>
    /// Read every module's joint pots (<c>pot_raw</c>) every this many cycles, half-way between status polls: one sync
    /// read, for the supervisor's pot/encoder check (<see cref="RobotMotor.PotPositionRad"/>). 0: never.
    /// </summary>
    public int PotPollCycles { get; init; } = 16;

    /// <summary>
    /// Read one module's per-motor detail (torque read back, motor errors: two reads) every this many cycles, the
    /// modules in turn, for a console's bus page (<see cref="RobotMotor.TorqueReadBack"/>, <see cref="RobotMotor.Errors"/>).
    /// 0: never (a run does not need it).
    /// </summary>
    public int DetailPollCycles { get; init; }

    /// <summary>Cycles a module may miss in a row before it is reported missing.</summary>
    public int MissingAfterCycles { get; init; } = 3;

    /// <summary>Cycles between attempts to reach a missing module again.</summary>
    public int ReprobeCycles { get; init; } = 200;

    /// <summary>Fraction of a motor's current limit from which it counts as current-limited.</summary>
    public double CurrentLimitedFraction { get; init; } = 0.9;

    /// <summary>Shortest time between cycle starts on the bus thread (zero: as fast as the bus allows).</summary>
    public TimeSpan MinimumCyclePeriod { get; init; } = TimeSpan.Zero;
}
