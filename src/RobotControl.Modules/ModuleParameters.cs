using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;

namespace RobotControl.Modules;

/// <summary>One persistent control-table value the robot file implies for a module.</summary>
/// <param name="Field">The control-table field.</param>
/// <param name="Motor">Motor instance (0 for module-wide fields).</param>
/// <param name="Value">The value in the field's own units.</param>
/// <param name="Meaning">What it is in the robot's units, for reports.</param>
public sealed record ParameterValue(ControlTableField Field, int Motor, long Value, string Meaning)
{
    /// <summary>Address of this instance.</summary>
    public ushort Address => Field.At(Motor);

    /// <inheritdoc />
    public override string ToString() => Field.Count > 1 ? $"{Field.Name}[{Motor}] = {Value} ({Meaning})" : $"{Field.Name} = {Value} ({Meaning})";
}

/// <summary>
/// Converts a module's entry in the robot file into the persistent control-table values its firmware keeps in FRAM:
/// gains, limits (from the joint limits through the coupling), pot calibration points, bus settings.
/// </summary>
public static class ModuleParameters
{
    /// <summary>Bit rate of each code of the control table's <c>baud_rate</c> field (its <c>codes</c>), indexed by code.</summary>
    private static readonly int[] BaudCodes = ReadBaudCodes();

    /// <summary>The baud code for <paramref name="baud"/>, or -1.</summary>
    public static int BaudCode(int baud) => Array.IndexOf(BaudCodes, baud);

    /// <summary>Every bit rate the modules can be set to, in code order.</summary>
    public static IReadOnlyList<int> Bauds => [.. BaudCodes.Where(b => b > 0)];

    /// <summary>The bit rate of a baud code.</summary>
    public static int BaudFromCode(int code) => code >= 0 && code < BaudCodes.Length ? BaudCodes[code] : 0;

    /// <summary>Every persistent value of module <paramref name="module"/> (motors in channel order).</summary>
    public static IReadOnlyList<ParameterValue> For(RobotDefinition robot, ModuleDefinition module, ControlTable table)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(module);
        ArgumentNullException.ThrowIfNull(table);
        var layout = robot.Modules;
        var values = new List<ParameterValue>
        {
            new(table["return_delay_time"], 0, layout.ReturnDelayUs / 2, $"{layout.ReturnDelayUs} us"),
            new(table["baud_rate"], 0, BaudCode(layout.BaudRate), $"{layout.BaudRate} baud"),
        };
        var tolerance = int.MaxValue;
        foreach (var motor in module.Motors.OrderBy(m => m.Channel))
        {
            var config = new MotorConfig(robot, module, motor);
            var ch = motor.Channel;
            values.AddRange(MotorParameter.All.Select(p => new ParameterValue(table[p.Field.Name], ch, p.FileCounts(config), p.FileText(config))));
            values.Add(new(table["control_mode"], ch, 0, "position"));
            values.Add(new(table["position_min"], ch, config.ToCounts(config.OutputMinRad), $"{config.OutputMinRad * 180 / Math.PI:F1} deg"));
            values.Add(new(table["position_max"], ch, config.ToCounts(config.OutputMaxRad), $"{config.OutputMaxRad * 180 / Math.PI:F1} deg"));

            // Pot calibration: points evenly spaced in Hall counts over the pot's calibrated range.
            var pot = motor.Pot;
            var cal = PotCalibrationTable.For(config);
            values.Add(new(table["pot_cal_count"], ch, cal.Count, "points"));
            values.Add(new(table["pot_cal_pos0"], ch, cal.Pos0, $"{pot.MinRad * 180 / Math.PI:F1} deg"));
            values.Add(new(table["pot_cal_step"], ch, cal.Step, $"{cal.Step / config.CountsPerRad * 180 / Math.PI:F2} deg"));
            for (var k = 0; k < cal.Count; k++)
            {
                var angle = config.ToRadians(cal.Pos0 + (k * cal.Step));
                values.Add(new(table[$"pot_cal_raw{k}"], ch, cal.Raw[k], $"pot at {angle * 180 / Math.PI:F1} deg"));
            }

            // A reset module may disagree with its pot by the pot's resolution plus backlash: allow 5 degrees of output.
            tolerance = Math.Min(tolerance, (int)Math.Round(5 * Math.PI / 180 * config.CountsPerRad));
        }

        if (module.Motors.Count > 0)
        {
            values.Add(new(table["pot_mismatch_tolerance"], 0, Math.Clamp(tolerance, 1, 65535), "5 deg of output"));
        }

        return values;
    }

    private static int[] ReadBaudCodes()
    {
        var codes = ControlTable.Firmware.Codes("baud_rate");
        var rates = new int[codes.Count == 0 ? 0 : codes.Keys.Max() + 1];
        foreach (var (code, rate) in codes)
        {
            rates[code] = int.Parse(rate, System.Globalization.CultureInfo.InvariantCulture);
        }

        return rates;
    }
}
