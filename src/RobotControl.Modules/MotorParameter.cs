using System.Globalization;
using RobotControl.Bus.Protocol;

namespace RobotControl.Modules;

/// <summary>
/// The units table: one persistent per-motor parameter in the robot's units (what the robot file gives) and the
/// control-table field that keeps it in FRAM, with the one conversion between them. The robot file's values
/// (<see cref="ModuleParameters"/>) and the console's edits both convert here; the values a field accepts are
/// <see cref="ParameterRules"/>' and are checked where every write goes (<see cref="ParameterWriter"/>).
/// </summary>
public sealed class MotorParameter
{
    private readonly Func<MotorConfig, double> _countsPerUnit;
    private readonly Func<MotorConfig, double> _fileValue;
    private readonly string _format;
    private readonly long _fileMinimum;

    private MotorParameter(string key, string label, string unit, string format, Func<MotorConfig, double> countsPerUnit, Func<MotorConfig, double> fileValue, long fileMinimum = long.MinValue)
    {
        Key = key;
        Label = label;
        Unit = unit;
        Field = ControlTable.Firmware[key];
        _format = format;
        _countsPerUnit = countsPerUnit;
        _fileValue = fileValue;
        _fileMinimum = fileMinimum;
    }

    /// <summary>The parameters, in display order.</summary>
    public static IReadOnlyList<MotorParameter> All { get; } =
    [
        new("gear_ratio", "gear ratio", ":1", "F3", _ => 1000, c => c.GearRatio),

        // kp counts are Q8.8 PWM (of 255) per Hall count: duty/rad * 255 / (counts/rad) * 256.
        new("kp", "P gain", "duty/rad", "G", c => 255.0 * 256.0 / c.CountsPerRad, c => c.Motor.Kp),
        new("current_limit", "current limit", "A", "G", c => c.RawPerAmp, c => c.Motor.CurrentLimitA),

        // A speed limit of 0 would hold the motor: the robot file's limit is at least one count per second.
        new("speed_limit", "max speed", "deg/s", "F1", c => c.CountsPerRad * Math.PI / 180, c => c.Motor.SpeedLimitRadS * 180 / Math.PI, fileMinimum: 1),
    ];

    /// <summary>Key in the API, the name of its control-table field.</summary>
    public string Key { get; }

    /// <summary>What it is.</summary>
    public string Label { get; }

    /// <summary>Unit of the values.</summary>
    public string Unit { get; }

    /// <summary>The control-table field.</summary>
    public ControlTableField Field { get; }

    /// <summary>The parameter with <paramref name="key"/>, or null.</summary>
    public static MotorParameter? Find(string key) => All.FirstOrDefault(p => p.Key == key);

    /// <summary>The robot file's value for <paramref name="motor"/>, in robot units.</summary>
    public double FileValue(MotorConfig motor) => _fileValue(motor);

    /// <summary>The robot file's value in module counts, held within what the field accepts.</summary>
    public long FileCounts(MotorConfig motor)
    {
        var (min, max) = ParameterRules.Range(Field);
        return (long)Math.Clamp(Math.Round(FileValue(motor) * _countsPerUnit(motor)), Math.Max(min, _fileMinimum), max);
    }

    /// <summary>The robot file's value with its unit, for reports (e.g. <c>25.000:1</c>, <c>1.5 A</c>).</summary>
    public string FileText(MotorConfig motor) =>
        FileValue(motor).ToString(_format, CultureInfo.CurrentCulture) + (Unit.StartsWith(':') ? Unit : " " + Unit);

    /// <summary>Module counts to robot units.</summary>
    public double FromCounts(MotorConfig motor, long counts) => counts / _countsPerUnit(motor);

    /// <summary>The values the field accepts (<see cref="ParameterRules.Range"/>), in robot units.</summary>
    public (double Min, double Max) Range(MotorConfig motor)
    {
        var (min, max) = ParameterRules.Range(Field);
        return (FromCounts(motor, min), FromCounts(motor, max));
    }

    /// <summary>
    /// Robot units to module counts, rounded; null (with the reason) when the value is no number a control-table field
    /// could be given. Whether the field accepts the counts is the writer's check, the same for every caller.
    /// </summary>
    public long? ToCounts(MotorConfig motor, double value, out string problem)
    {
        const double Largest = 1L << 53; // beyond any field, and still an exact integer
        var counts = Math.Round(value * _countsPerUnit(motor));
        problem = double.IsFinite(counts) && Math.Abs(counts) <= Largest
            ? string.Empty
            : string.Create(CultureInfo.InvariantCulture, $"{Key} = {value:G6} {Unit} is no value {Field.Name} can hold (give a finite number)");
        return problem.Length == 0 ? (long)counts : null;
    }
}
