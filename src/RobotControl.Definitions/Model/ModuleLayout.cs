namespace RobotControl.Definitions.Model;

/// <summary>
/// The motor-control modules of a robot (the file's <c>modules</c> section): bus settings and, per module, its ID,
/// friendly name, arm and the motors it drives. Empty when the file has no such section.
/// </summary>
/// <param name="BaudRate">Bus speed the modules are configured for, bits/s.</param>
/// <param name="WatchdogMs">
/// Bus watchdog, stage 1: when no frame for it arrives for this long, a module holds every motor where it is (and
/// refuses new goals until the host acknowledges the hold).
/// </param>
/// <param name="WatchdogOffMs">
/// Bus watchdog, stage 2: when no frame for it arrives for this long (frames during a hold count), a module switches
/// its motors off; longer than <paramref name="WatchdogMs"/>.
/// </param>
/// <param name="ReturnDelayUs">Module reply delay, microseconds.</param>
/// <param name="Modules">The modules, in file order.</param>
public sealed record ModuleLayout(int BaudRate, int WatchdogMs, int WatchdogOffMs, int ReturnDelayUs, IReadOnlyList<ModuleDefinition> Modules)
{
    /// <summary>The robot file's <c>modules.watchdog_off_ms</c> when it gives none, ms.</summary>
    public const int DefaultWatchdogOffMs = 500;

    /// <summary>
    /// Longest watchdog stage a robot file may give, ms: the range of the modules' <c>bus_watchdog</c> and
    /// <c>bus_watchdog_off</c> (firmware/protocol/control-table.json; a test holds the two together).
    /// </summary>
    public const int MaxWatchdogMs = 60_000;

    /// <summary>A robot without modules.</summary>
    public static ModuleLayout Empty { get; } = new(1_000_000, 100, DefaultWatchdogOffMs, 0, []);

    /// <summary>The module with bus ID <paramref name="id"/>, or null.</summary>
    public ModuleDefinition? ById(int id)
    {
        foreach (var m in Modules)
        {
            if (m.Id == id)
            {
                return m;
            }
        }

        return null;
    }
}

/// <summary>One motor-control module.</summary>
/// <param name="Id">Bus ID (1..252).</param>
/// <param name="Name">Friendly name, e.g. <c>right shoulder</c>.</param>
/// <param name="Arm">Index of the arm (in the file's <c>arms</c>) the module belongs to.</param>
/// <param name="Location">Where it sits, e.g. <c>shoulder</c>, <c>upper_arm</c>, <c>forearm</c>.</param>
/// <param name="CurrentSenseFullScaleA">Motor current at the current ADC's full scale (4095), A: the module's shunt and amplifier.</param>
/// <param name="Motors">Motors on the module's channels.</param>
public sealed record ModuleDefinition(byte Id, string Name, int Arm, string Location, double CurrentSenseFullScaleA, IReadOnlyList<ModuleMotorDefinition> Motors)
{
    /// <summary>Current ADC counts per ampere of a module whose full scale is <paramref name="fullScaleA"/>: the one conversion from amperes to the module's current units (the ADC is the pots' 12-bit one).</summary>
    public static double RawPerAmpOf(double fullScaleA) => PotCalibration.AdcFullScale / fullScaleA;

    /// <summary>Current ADC counts per ampere (<see cref="RawPerAmpOf"/>).</summary>
    public double RawPerAmp => RawPerAmpOf(CurrentSenseFullScaleA);
}

/// <summary>One motor on a module channel, with the parameters the module keeps in FRAM.</summary>
/// <param name="Channel">Bridge channel on the module (0..3).</param>
/// <param name="ActuatorIndex">Index into the robot's <c>actuators</c>; the motor is named after that axis.</param>
/// <param name="Kp">Proportional gain: PWM duty (fraction of full scale) per radian of output position error.</param>
/// <param name="CurrentLimitA">Filtered current limit, A.</param>
/// <param name="SpeedLimitRadS">Maximum output speed, rad/s.</param>
/// <param name="HallCountsPerRev">Hall edges per motor revolution (6 per pole pair).</param>
/// <param name="Pot">The output potentiometer and its calibration.</param>
public sealed record ModuleMotorDefinition(
    int Channel,
    int ActuatorIndex,
    double Kp,
    double CurrentLimitA,
    double SpeedLimitRadS,
    int HallCountsPerRev,
    PotCalibration Pot);

/// <summary>
/// An absolute potentiometer on an axis output, read by a 12-bit ADC: linear from (<see cref="MinRad"/>,
/// <see cref="AdcAtMin"/>) to (<see cref="MaxRad"/>, <see cref="AdcAtMax"/>) plus a bow of <see cref="BowCounts"/> ADC
/// counts at mid-range (its non-linearity, sin-shaped over the range).
/// </summary>
/// <param name="MinRad">Output angle at the calibration's low end, radians.</param>
/// <param name="MaxRad">Output angle at the calibration's high end, radians.</param>
/// <param name="AdcAtMin">ADC counts at <paramref name="MinRad"/>.</param>
/// <param name="AdcAtMax">ADC counts at <paramref name="MaxRad"/>.</param>
/// <param name="BowCounts">Deviation from the line at mid-range, ADC counts.</param>
public sealed record PotCalibration(double MinRad, double MaxRad, double AdcAtMin, double AdcAtMax, double BowCounts)
{
    /// <summary>ADC full scale (12 bits).</summary>
    public const int AdcFullScale = 4095;

    /// <summary>The ADC reading at output angle <paramref name="angleRad"/> (non-linear, clamped to the ADC range).</summary>
    public double Reading(double angleRad)
    {
        var u = (angleRad - MinRad) / (MaxRad - MinRad);
        var linear = AdcAtMin + (u * (AdcAtMax - AdcAtMin));
        return Math.Clamp(linear + (BowCounts * Math.Sin(Math.PI * u)), 0, AdcFullScale);
    }

    /// <summary>The output angle for ADC reading <paramref name="adc"/>, inverting <see cref="Reading"/> (Newton).</summary>
    public double Angle(double adc)
    {
        var span = MaxRad - MinRad;
        var u = (adc - AdcAtMin) / (AdcAtMax - AdcAtMin);
        for (var i = 0; i < 20; i++)
        {
            var f = AdcAtMin + (u * (AdcAtMax - AdcAtMin)) + (BowCounts * Math.Sin(Math.PI * u)) - adc;
            var df = (AdcAtMax - AdcAtMin) + (BowCounts * Math.PI * Math.Cos(Math.PI * u));
            u -= f / df;
        }

        return MinRad + (u * span);
    }
}
