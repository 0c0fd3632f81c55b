namespace RobotControl.Simulation;

/// <summary>How a <see cref="VirtualRobot"/> is set up.</summary>
public sealed record VirtualRobotOptions
{
    /// <summary>
    /// Bus speed the modules are commissioned to; null: the robot file's <c>modules.baud</c>. Uncommissioned modules
    /// stay at the factory baud, so only that speed reaches them.
    /// </summary>
    public int? BaudRate { get; init; }

    /// <summary>Seed of every random source (sensor noise, wire faults): the same seed repeats a run exactly.</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Joint angles (radians, one array per arm) the arms rest at when powered on; null: mid-range.</summary>
    public IReadOnlyList<double[]>? InitialJointsRad { get; init; }

    /// <summary>Jaw angle at power-on, radians; null: mid-range.</summary>
    public double? InitialJawRad { get; init; }

    /// <summary>
    /// True: the modules' FRAM gets the robot file's parameters (through the bus) and they restart, as after
    /// commissioning; false: they start blank with factory defaults.
    /// </summary>
    public bool Commissioned { get; init; } = true;

    /// <summary>Standard deviation of the current readings, ADC counts.</summary>
    public double CurrentNoiseCounts { get; init; } = 2;

    /// <summary>Standard deviation of the pot readings, ADC counts.</summary>
    public double PotNoiseCounts { get; init; } = 1;

    /// <summary>Step of the motor models (the firmware runs its own 10 kHz tick in between).</summary>
    public TimeSpan PhysicsStep { get; init; } = TimeSpan.FromMicroseconds(50);

    /// <summary>Gearhead backlash at the gearhead output, degrees (the catalogue's worst case is 3).</summary>
    public double BacklashDeg { get; init; } = 1;
}
