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

    /// <summary>
    /// True: a box of boards fresh from the factory. Every module has blank FRAM (the firmware's defaults, at the
    /// control table's default ID and baud; nothing commissioned, whatever <see cref="Commissioned"/> says), and only
    /// the first <see cref="ConnectedAtStart"/> are plugged in; <see cref="VirtualRobot.ConnectNext"/> plugs in the
    /// next, as a lab connects one board at a time.
    /// </summary>
    public bool Factory { get; init; }

    /// <summary>With <see cref="Factory"/>: how many modules (in the robot file's order) are plugged in at power-on.</summary>
    public int ConnectedAtStart { get; init; }

    /// <summary>
    /// Seed of this unit's pot curves: each pot's true curve differs from the robot file's design curve by an offset,
    /// a gain and a bow drawn within <see cref="Units.PotVariationBounds.Default"/> (same seed, same unit). Null: the
    /// pots follow the design curves.
    /// </summary>
    public int? UnitVariationSeed { get; init; }

    /// <summary>Standard deviation of the current readings, ADC counts.</summary>
    public double CurrentNoiseCounts { get; init; } = 2;

    /// <summary>Standard deviation of the pot readings, ADC counts.</summary>
    public double PotNoiseCounts { get; init; } = 1;

    /// <summary>Step of the motor models (the firmware runs its own 10 kHz tick in between).</summary>
    public TimeSpan PhysicsStep { get; init; } = TimeSpan.FromMicroseconds(50);

    /// <summary>Gearhead backlash at the gearhead output, degrees (the catalogue's worst case is 3).</summary>
    public double BacklashDeg { get; init; } = 1;

    /// <summary>Refuses factory settings that cannot be: a commissioned baud, more modules plugged in than <paramref name="modules"/>, plugging in without <see cref="Factory"/>.</summary>
    /// <exception cref="ArgumentException">The message names the setting.</exception>
    internal void CheckFactory(int modules)
    {
        if (!Factory)
        {
            if (ConnectedAtStart != 0)
            {
                throw new ArgumentException("ConnectedAtStart: only modules from the factory are plugged in one at a time (set Factory)");
            }

            return;
        }

        if (BaudRate is { } baud && baud != VirtualRobot.FactoryBaud)
        {
            throw new ArgumentException($"BaudRate {baud}: modules from the factory run at the factory baud ({VirtualRobot.FactoryBaud}); commissioning moves them");
        }

        if (ConnectedAtStart < 0 || ConnectedAtStart > modules)
        {
            throw new ArgumentException($"ConnectedAtStart {ConnectedAtStart}: the robot has {modules} modules");
        }
    }
}
