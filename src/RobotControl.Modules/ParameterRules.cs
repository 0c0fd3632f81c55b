using System.Globalization;
using RobotControl.Bus.Protocol;

namespace RobotControl.Modules;

/// <summary>
/// What the host checks before it stores a module parameter, so that a module never keeps a value nobody asked for:
/// each value against its control-table field (writable, within the field's range and type, no cast that truncates),
/// and the rules that tie fields together per motor (position_min below position_max; a pot calibration of 0 or 2..8
/// points, strictly monotonic, with a non-zero step), checked on the module's table as it would be after the write.
/// A value that switches a protection off (0 in a field the control table marks <c>zero_disables</c>: the current
/// limit, the speed limit, the bus watchdog) is not an ordinary value: it is refused unless the caller says, on
/// purpose, that a protection may go off (<see cref="ProtectionOff"/>; the console never does, <c>robotctl params set
/// --allow-protection-off</c> does).
/// </summary>
public static class ParameterRules
{
    /// <summary>
    /// Why <paramref name="value"/> cannot be stored in <paramref name="field"/>, or null when it can. A value that
    /// switches a protection off is refused unless <paramref name="allowProtectionOff"/>.
    /// </summary>
    public static string? CheckValue(ControlTableField field, long value, bool allowProtectionOff = false)
    {
        ArgumentNullException.ThrowIfNull(field);
        if (!field.Writable)
        {
            return $"{field.Name} is read-only";
        }

        var (min, max) = Range(field);
        if (value < min || value > max)
        {
            return string.Create(CultureInfo.InvariantCulture, $"{field.Name} = {value} is outside its range {min}..{max} ({field.Type}{(field.Unit.Length > 0 ? ", " + field.Unit : string.Empty)})");
        }

        return !allowProtectionOff && ProtectionOff(field, value) is { } off
            ? $"{off}; a protection goes off only on purpose (robotctl params set --allow-protection-off)"
            : null;
    }

    /// <summary>
    /// What <paramref name="value"/> in <paramref name="field"/> switches off (e.g. "current_limit = 0 switches the
    /// motor's current limit off"), or null when it switches nothing off.
    /// </summary>
    public static string? ProtectionOff(ControlTableField field, long value)
    {
        ArgumentNullException.ThrowIfNull(field);
        return value == 0 && field.ZeroDisables is { } protection ? $"{field.Name} = 0 switches {protection} off" : null;
    }

    /// <summary>The values <paramref name="field"/> accepts: its own range within what its type holds.</summary>
    public static (long Min, long Max) Range(ControlTableField field)
    {
        ArgumentNullException.ThrowIfNull(field);
        var (typeMin, typeMax) = TypeRange(field);
        return (Math.Max((long)field.Min, typeMin), Math.Min((long)field.Max, typeMax));
    }

    /// <summary>
    /// The cross-field problems of motor <paramref name="motor"/> in a module whose persistent values
    /// <paramref name="value"/> returns (after the intended writes). Only the rules that involve
    /// <paramref name="changed"/> are checked when it is given (a module already out of line can still be repaired
    /// one field at a time); all of them when it is null.
    /// </summary>
    public static IReadOnlyList<string> CheckMotor(Func<string, int, long> value, int motor, string? changed = null)
    {
        ArgumentNullException.ThrowIfNull(value);
        var problems = new List<string>();
        if (Involves(changed, "position_min", "position_max"))
        {
            var (min, max) = (value("position_min", motor), value("position_max", motor));
            if (min >= max)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"motor {motor}: position_min {min} must be below position_max {max}"));
            }
        }

        if (changed is null || changed == "pot_cal_count" || changed == "pot_cal_step" || changed.StartsWith("pot_cal_raw", StringComparison.Ordinal))
        {
            var count = value("pot_cal_count", motor);
            if (count == 1 || count < 0 || count > PotCalibrationTable.MaxPoints)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"motor {motor}: pot_cal_count {count} must be 0 (no pot homing) or 2..{PotCalibrationTable.MaxPoints} points"));
            }
            else if (count >= 2)
            {
                if (value("pot_cal_step", motor) == 0)
                {
                    problems.Add($"motor {motor}: pot_cal_step is 0, so the {count} calibration points coincide");
                }

                var raws = Enumerable.Range(0, (int)count).Select(k => value($"pot_cal_raw{k}", motor)).ToArray();
                var rising = raws.Zip(raws.Skip(1)).All(p => p.Second > p.First);
                var falling = raws.Zip(raws.Skip(1)).All(p => p.Second < p.First);
                if (!rising && !falling)
                {
                    problems.Add($"motor {motor}: pot calibration points pot_cal_raw0..{count - 1} ({string.Join(", ", raws)}) must be strictly increasing or strictly decreasing");
                }
            }
        }

        return problems;
    }

    private static bool Involves(string? changed, params string[] fields) => changed is null || fields.Contains(changed);

    private static (long Min, long Max) TypeRange(ControlTableField field) => field.Type switch
    {
        "u8" => (byte.MinValue, byte.MaxValue),
        "u16" => (ushort.MinValue, ushort.MaxValue),
        "u32" => (uint.MinValue, uint.MaxValue),
        "i16" => (short.MinValue, short.MaxValue),
        "i32" => (int.MinValue, int.MaxValue),
        _ => throw new InvalidOperationException($"{field.Name}: unknown type {field.Type}"),
    };
}
