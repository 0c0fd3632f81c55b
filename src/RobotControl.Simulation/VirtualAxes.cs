using RobotControl.Definitions.Model;
using RobotControl.Modules;
using RobotControl.Simulation.Models;
using RobotControl.Simulation.Native;
using RobotControl.Simulation.Units;

namespace RobotControl.Simulation;

/// <summary>
/// Every simulated motor of a <see cref="VirtualRobot"/> (its drivetrain model, Hall sensors, current sense and pot),
/// built from the robot file, stepped with the PWM its firmware applies, and feeding the firmware's sensor inputs.
/// </summary>
internal sealed class VirtualAxes
{
    private readonly VirtualRobotOptions _options;
    private readonly NoiseSource _sensorNoise;

    public VirtualAxes(RobotDefinition robot, ModuleDefinition[] modules, VirtualRobotOptions options)
    {
        _options = options;
        _sensorNoise = new NoiseSource(options.Seed);
        var axes = new List<VirtualAxis>();
        var variations = options.UnitVariationSeed is { } unit
            ? PotVariation.Draw(unit, modules.Sum(m => m.Motors.Count), PotVariationBounds.Default)
            : null;
        for (var mi = 0; mi < modules.Length; mi++)
        {
            foreach (var motor in modules[mi].Motors)
            {
                var config = new MotorConfig(robot, modules[mi], motor);
                var actuator = config.Actuator;
                var model = new DrivetrainModel(actuator, robot.Motor(actuator.Drivetrain.MotorModel), options.BacklashDeg * Math.PI / 180, LinkInertia(actuator))
                {
                    HardStops = (config.OutputMinRad - 0.05, config.OutputMaxRad + 0.05),
                };
                model.Reset(InitialOutput(robot, config));
                axes.Add(new VirtualAxis(config, mi, model, variations?[axes.Count] ?? PotVariation.None));
            }
        }

        All = axes.ToArray();
        foreach (var axis in All)
        {
            axis.LastSector = Sector(axis);
        }
    }

    /// <summary>Every axis, modules in file order, motors in file order.</summary>
    public VirtualAxis[] All { get; }

    /// <summary>The Hall sector the rotor of <paramref name="axis"/> is in.</summary>
    public static int Sector(VirtualAxis axis) => (int)Math.Floor(axis.Model.RotorAngle * axis.Motor.PolePairs / (Math.PI / 3));

    /// <summary>Gives the firmware on <paramref name="bus"/> the Hall code of <paramref name="axis"/>'s rotor as it is now.</summary>
    public static void SetHall(nint bus, VirtualAxis axis) =>
        _ = FirmwareHost.SetHall(bus, axis.ModuleIndex, axis.Config.Channel, (byte)(axis.HallFailedCode ?? HallSensors.Code(axis.Model.RotorAngle, axis.Motor.PolePairs)));

    /// <summary>Steps every model <paramref name="dt"/> seconds with the PWM its firmware applies, then feeds the sensors.</summary>
    public void Step(nint bus, double dt)
    {
        foreach (var axis in All)
        {
            var pwm = FirmwareHost.GetPwm(bus, axis.ModuleIndex, axis.Config.Channel);
            var enabled = FirmwareHost.GetDriverEnable(bus, axis.ModuleIndex, axis.Config.Channel) == 1;
            axis.Pwm = pwm;
            axis.DriverEnabled = enabled;
            axis.Model.Step(pwm / 255.0, enabled, dt);

            // Hall edges in order, as the pin interrupts would see them, however far the rotor turned; a failed
            // connector holds its one code (the firmware sees an edge only when the lines change).
            var sector = Sector(axis);
            if (axis.HallFailedCode is { } stuck)
            {
                _ = FirmwareHost.SetHall(bus, axis.ModuleIndex, axis.Config.Channel, (byte)stuck);
                axis.LastSector = sector;
                continue;
            }

            var direction = Math.Sign(sector - axis.LastSector);
            var guard = 0;
            while (axis.LastSector != sector && guard++ < 64)
            {
                axis.LastSector += direction;
                var code = HallSensors.Code(((axis.LastSector + 0.5) * Math.PI / 3) / axis.Motor.PolePairs, axis.Motor.PolePairs);
                _ = FirmwareHost.SetHall(bus, axis.ModuleIndex, axis.Config.Channel, code);
            }

            axis.LastSector = sector;
        }

        Feed(bus);
    }

    /// <summary>Gives the firmware on <paramref name="bus"/> every axis's current and pot readings (with their noise).</summary>
    public void Feed(nint bus)
    {
        foreach (var axis in All)
        {
            var current = (Math.Abs(axis.Model.Current) + axis.CurrentSenseOffsetA) * axis.Config.RawPerAmp + _sensorNoise.Gaussian(_options.CurrentNoiseCounts);
            _ = FirmwareHost.SetCurrentRaw(bus, axis.ModuleIndex, axis.Config.Channel, (ushort)Math.Clamp(Math.Round(current), 0, 4095));
            var noise = _sensorNoise.Gaussian(_options.PotNoiseCounts);
            var pot = axis.PotFailedRaw ?? (axis.TruePot.Reading(axis.Model.OutputAngle) + noise);
            _ = FirmwareHost.SetPotRaw(bus, axis.ModuleIndex, axis.Config.Channel, (ushort)Math.Clamp(Math.Round(pot), 0, 4095));
        }
    }

    // A link's inertia at the axis output, kg m^2: a few grams at a few centimetres (no mass data in the design).
    private static double LinkInertia(ActuatorDefinition actuator) => actuator.IsKinematic ? 2e-5 : 1e-7;

    private double InitialOutput(RobotDefinition robot, MotorConfig config)
    {
        if (!config.Actuator.IsKinematic)
        {
            return _options.InitialJawRad ?? (0.5 * (robot.Tool.JawMinRad + robot.Tool.JawMaxRad));
        }

        var q = _options.InitialJointsRad is { } given && config.Arm < given.Count ? given[config.Arm] : robot.Joints.Select(j => j.MidRad).ToArray();
        var a = 0.0;
        for (var j = 0; j < robot.JointCount; j++)
        {
            a += config.Actuator.Coupling[j] * q[j];
        }

        return a;
    }
}
