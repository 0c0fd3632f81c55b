using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Robot.Commissioning;

/// <summary>What <c>discover --unit</c> compares: every module of a unit file against the bus (it answers at its ID, with its firmware version, and every recorded parameter reads back as recorded).</summary>
public static class UnitCheck
{
    /// <summary>
    /// The differences from the robot file in <paramref name="mismatches"/> that are <paramref name="unit"/>'s pot
    /// calibration: a <c>pot_cal_*</c> value of a motor the unit file has a calibration for, holding the value it recorded.
    /// </summary>
    public static IReadOnlyList<ParameterMismatch> Calibrated(IReadOnlyList<ParameterMismatch> mismatches, UnitFile unit)
    {
        ArgumentNullException.ThrowIfNull(mismatches);
        ArgumentNullException.ThrowIfNull(unit);
        return [.. mismatches.Where(m => m.Expected.Field.Name.StartsWith("pot_cal_", StringComparison.Ordinal)
            && unit.Module(m.ModuleId) is { PotCalibration.Count: > 0 } module
            && module.Parameters.TryGetValue(UnitFile.Key(m.Expected.Field, m.Expected.Motor), out var recorded)
            && recorded == m.Actual)];
    }

    /// <summary>One line per difference, naming the module and what differs (none: the unit is as commissioned).</summary>
    public static IReadOnlyList<string> Differences(BusClient client, UnitFile unit)
    {
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(unit);
        var table = ControlTable.Firmware;
        var reader = new ParameterWriter(client, table);
        var lines = new List<string>();
        foreach (var module in unit.Modules)
        {
            var what = $"module {module.Id} ({module.Name})";
            if (client.Ping(module.Id, out var info).Outcome != ReplyOutcome.Ok)
            {
                lines.Add($"{what}: does not answer at id {module.Id}");
                continue;
            }

            if (info.FirmwareVersion != module.FirmwareVersion)
            {
                lines.Add($"{what}: firmware {info.FirmwareVersion}, the unit file says {module.FirmwareVersion}");
            }

            foreach (var (key, recorded) in module.Parameters)
            {
                var (field, motor) = UnitFile.Parse(table, key);
                var actual = reader.Read(module.Id, field.Name, motor);
                if (actual != recorded)
                {
                    lines.Add($"{what}: {key} is {actual}, the unit file says {recorded}");
                }
            }
        }

        return lines;
    }
}
