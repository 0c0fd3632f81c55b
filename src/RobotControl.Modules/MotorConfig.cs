using RobotControl.Definitions.Model;

namespace RobotControl.Modules;

/// <summary>
/// One motor as the robot file configures it: where it sits on the bus (module ID and channel), which axis of which
/// arm it drives, and the conversions between the module's integer units (Hall counts, current ADC counts) and the
/// robot's (radians at the axis output, amperes). Immutable.
/// </summary>
public sealed class MotorConfig
{
    /// <summary>Builds the configuration of <paramref name="motor"/> on <paramref name="module"/> of <paramref name="robot"/>.</summary>
    public MotorConfig(RobotDefinition robot, ModuleDefinition module, ModuleMotorDefinition motor)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(module);
        ArgumentNullException.ThrowIfNull(motor);
        Module = module;
        Motor = motor;
        Arm = module.Arm;
        ArmName = robot.Arms[module.Arm].Name;
        Actuator = robot.Actuators[motor.ActuatorIndex];
        ActuatorIndex = motor.ActuatorIndex;
        Name = MotorName.Of(Actuator, robot.Joints);
        GearRatio = Actuator.Drivetrain.TotalRatio;
        CountsPerRad = motor.HallCountsPerRev * GearRatio / (2 * Math.PI);
        RawPerAmp = module.RawPerAmp;
        (OutputMinRad, OutputMaxRad) = OutputRange(robot, Actuator);
    }

    /// <summary>The module carrying the motor.</summary>
    public ModuleDefinition Module { get; }

    /// <summary>The motor's entry in the module.</summary>
    public ModuleMotorDefinition Motor { get; }

    /// <summary>Bus ID of the module.</summary>
    public byte ModuleId => Module.Id;

    /// <summary>Channel on the module.</summary>
    public int Channel => Motor.Channel;

    /// <summary>Arm index.</summary>
    public int Arm { get; }

    /// <summary>Arm name.</summary>
    public string ArmName { get; }

    /// <summary>The axis the motor drives.</summary>
    public ActuatorDefinition Actuator { get; }

    /// <summary>Index of the axis in the robot file's <c>actuators</c>.</summary>
    public int ActuatorIndex { get; }

    /// <summary>The motor's name: the joint it is listed against (or the axis name for the tool drive).</summary>
    public string Name { get; }

    /// <summary><c>arm.name</c>, unique in the robot.</summary>
    public string FullName => MotorName.Full(ArmName, Name);

    /// <summary>Total reduction motor to axis output.</summary>
    public double GearRatio { get; }

    /// <summary>Hall counts per radian of axis output.</summary>
    public double CountsPerRad { get; }

    /// <summary>Current ADC counts per ampere.</summary>
    public double RawPerAmp { get; }

    /// <summary>Smallest axis output angle the joint limits allow, radians.</summary>
    public double OutputMinRad { get; }

    /// <summary>Largest axis output angle the joint limits allow, radians.</summary>
    public double OutputMaxRad { get; }

    /// <summary>Hall counts for an axis output angle.</summary>
    public int ToCounts(double outputRad) => (int)Math.Round(Math.Clamp(outputRad * CountsPerRad, int.MinValue, int.MaxValue));

    /// <summary>Axis output angle for a Hall count.</summary>
    public double ToRadians(long counts) => counts / CountsPerRad;

    /// <summary>Amperes for a current ADC reading.</summary>
    public double ToAmps(long raw) => raw / RawPerAmp;

    /// <inheritdoc />
    public override string ToString() => $"{FullName} (module {ModuleId} \"{Module.Name}\" channel {Channel})";

    /// <summary>The interval of C·q over the joint-limit box (the tool drive: the jaw range).</summary>
    private static (double Min, double Max) OutputRange(RobotDefinition robot, ActuatorDefinition actuator)
    {
        if (!actuator.IsKinematic)
        {
            return (robot.Tool.JawMinRad, robot.Tool.JawMaxRad);
        }

        double lo = 0, hi = 0;
        for (var j = 0; j < robot.JointCount; j++)
        {
            var c = actuator.Coupling[j];
            var a = c * robot.Joints[j].MinRad;
            var b = c * robot.Joints[j].MaxRad;
            lo += Math.Min(a, b);
            hi += Math.Max(a, b);
        }

        return (lo, hi);
    }
}
