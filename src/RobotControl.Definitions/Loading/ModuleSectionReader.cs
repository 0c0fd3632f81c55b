using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>
/// Reads and validates a robot file's optional <c>modules</c> section (bus settings and the motor-control modules:
/// IDs, friendly names, arms, motors with their FRAM parameters and potentiometer calibration).
/// </summary>
internal static class ModuleSectionReader
{
    private const double Deg = Math.PI / 180.0;

    public static ModuleLayout Read(JsonFieldReader root, IReadOnlyList<ActuatorDefinition> actuators, IReadOnlyList<ArmPlacement> arms)
    {
        var section = root.Object("modules", required: false);
        if (section is null)
        {
            return ModuleLayout.Empty;
        }

        var sink = section.Sink;
        var baud = section.Integer("baud", 9600, 20_000_000);
        // 0 (off) and the order of the two stages are refused against the safety section (SafetySectionReader)
        var watchdog = section.Integer("watchdog_ms", 0, ModuleLayout.MaxWatchdogMs);
        var watchdogOff = section.IntegerOrNull("watchdog_off_ms", 0, ModuleLayout.MaxWatchdogMs, required: false) ?? ModuleLayout.DefaultWatchdogOffMs;
        var returnDelay = section.Integer("return_delay_us", 0, 508);
        var modules = new List<ModuleDefinition>();
        var ids = new HashSet<int>();
        var names = new HashSet<string>(StringComparer.Ordinal);
        var driven = new HashSet<(int Arm, int Actuator)>();
        var items = section.Array("layout", nonEmpty: true) ?? [];
        for (var i = 0; i < items.Count; i++)
        {
            var m = new JsonFieldReader(sink, items[i], $"{section.Path}.layout[{i}]");
            if (!m.IsObject)
            {
                sink.Add(m.Path, "must be an object");
                continue;
            }

            var id = m.Integer("id", 1, 252);
            if (!ids.Add(id))
            {
                sink.Add(m.FieldPath("id"), $"duplicate module ID {id}");
            }

            var name = m.String("name");
            if (name.Length > 0 && !names.Add(name))
            {
                sink.Add(m.FieldPath("name"), $"duplicate module name \"{name}\"");
            }

            var armName = m.String("arm");
            var arm = -1;
            for (var a = 0; a < arms.Count; a++)
            {
                if (arms[a].Name == armName)
                {
                    arm = a;
                }
            }

            if (armName.Length > 0 && arm < 0)
            {
                sink.Add(m.FieldPath("arm"), $"refers to arm \"{armName}\", which $.arms does not define ({string.Join(", ", arms.Select(a => a.Name))})");
            }

            var location = m.String("location");
            var fullScale = m.Number("current_sense_full_scale_A", min: 0.001, max: 100);
            var motors = new List<ModuleMotorDefinition>();
            var channels = new HashSet<int>();
            var motorItems = m.Array("motors") ?? [];
            if (motorItems.Count > 4)
            {
                sink.Add(m.FieldPath("motors"), $"a module drives at most 4 motors, found {motorItems.Count}");
            }

            for (var k = 0; k < motorItems.Count; k++)
            {
                var mm = new JsonFieldReader(sink, motorItems[k], $"{m.FieldPath("motors")}[{k}]");
                var channel = mm.Integer("channel", 0, 3);
                if (!channels.Add(channel))
                {
                    sink.Add(mm.FieldPath("channel"), $"channel {channel} is used twice on module {id}");
                }

                var actuatorName = mm.String("actuator");
                var actuator = -1;
                for (var a = 0; a < actuators.Count; a++)
                {
                    if (actuators[a].Name == actuatorName)
                    {
                        actuator = a;
                    }
                }

                if (actuatorName.Length > 0 && actuator < 0)
                {
                    sink.Add(mm.FieldPath("actuator"), $"refers to actuator \"{actuatorName}\", which $.actuators does not define");
                }
                else if (actuator >= 0 && arm >= 0 && !driven.Add((arm, actuator)))
                {
                    sink.Add(mm.FieldPath("actuator"), $"actuator \"{actuatorName}\" of arm \"{armName}\" is driven by more than one module");
                }

                var kp = mm.Number("kp_duty_per_rad", min: 0, max: 1000);
                var current = mm.Number("current_limit_A", min: 0.001, max: 10);
                if (double.IsFinite(current) && double.IsFinite(fullScale) && current >= fullScale)
                {
                    sink.Add(mm.FieldPath("current_limit_A"), $"is {current}; must be below the module's current_sense_full_scale_A ({fullScale})");
                }
                else if (!sink.HasProblemAt(mm.FieldPath("current_limit_A")) && !sink.HasProblemAt(m.FieldPath("current_sense_full_scale_A")) && double.IsFinite(current) && double.IsFinite(fullScale) && fullScale > 0 && Math.Round(current * ModuleDefinition.RawPerAmpOf(fullScale)) < 1)
                {
                    // The module keeps the limit in ADC counts, and a limit of 0 counts switches its current limiter off.
                    var least = 0.5 / ModuleDefinition.RawPerAmpOf(fullScale);
                    sink.Add(mm.FieldPath("current_limit_A"), string.Create(System.Globalization.CultureInfo.InvariantCulture, $"is {current} A, which the module keeps as 0 current counts (current_sense_full_scale_A {fullScale} A = {PotCalibration.AdcFullScale} counts), and a current limit of 0 switches the module's current limiter off; give at least {least:G3} A"));
                }

                var speed = mm.Number("speed_limit_deg_s", min: 0.1, max: 100_000);
                var hall = mm.Integer("hall_counts_per_rev", 1, 1024);
                var pot = ReadPot(mm.Object("pot"));
                mm.RejectUnknownFields();
                motors.Add(new ModuleMotorDefinition(channel, actuator, kp, current, speed * Deg, hall, pot!));
            }

            m.RejectUnknownFields();
            modules.Add(new ModuleDefinition((byte)id, name, arm, location, fullScale, motors));
        }

        section.RejectUnknownFields();
        return new ModuleLayout(baud, watchdog, watchdogOff, returnDelay, modules);
    }

    private static PotCalibration? ReadPot(JsonFieldReader? p)
    {
        if (p is null)
        {
            return null;
        }

        var min = p.Number("min_deg", -3600, 3600);
        var max = p.Number("max_deg", -3600, 3600);
        var adcMin = p.Number("adc_at_min", 0, PotCalibration.AdcFullScale);
        var adcMax = p.Number("adc_at_max", 0, PotCalibration.AdcFullScale);
        var bow = p.Number("bow_counts", -1000, 1000);
        if (min >= max)
        {
            p.Sink.Add(p.Path, $"pot range has min_deg {min} >= max_deg {max}");
        }

        if (Math.Abs(adcMax - adcMin) < 100)
        {
            p.Sink.Add(p.Path, $"adc_at_min {adcMin} and adc_at_max {adcMax} are too close to resolve the angle");
        }
        else if (Math.Abs(bow) * Math.PI >= Math.Abs(adcMax - adcMin))
        {
            p.Sink.Add(p.FieldPath("bow_counts"), $"is {bow}; the curve must stay monotonic (|bow| * pi < |adc_at_max - adc_at_min|)");
        }

        p.RejectUnknownFields();
        return new PotCalibration(min * Deg, max * Deg, adcMin, adcMax, bow);
    }
}
