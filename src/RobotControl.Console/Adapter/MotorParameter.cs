using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// One persistent per-motor parameter the console edits, in the robot's units (what the robot file gives) and the
/// control-table field that keeps it in FRAM. The conversion is exact both ways: a value that rounds outside what the
/// field's type can hold is refused here; a value the field can hold but the firmware refuses (its own range) is sent,
/// and the module's error is reported.
/// </summary>
internal sealed class MotorParameter
{
    private readonly Func<MotorConfig, double> _countsPerUnit;
    private readonly Func<MotorConfig, double> _fileValue;

    private MotorParameter(string key, string label, string unit, string field, Func<MotorConfig, double> countsPerUnit, Func<MotorConfig, double> fileValue)
    {
        Key = key;
        Label = label;
        Unit = unit;
        Field = ControlTable.Firmware[field];
        _countsPerUnit = countsPerUnit;
        _fileValue = fileValue;
    }

    /// <summary>The parameters, in display order.</summary>
    public static IReadOnlyList<MotorParameter> All { get; } =
    [
        new("gear_ratio", "gear ratio", ":1", "gear_ratio", _ => 1000, c => c.GearRatio),

        // kp counts are Q8.8 PWM (of 255) per Hall count: duty/rad * 255 / (counts/rad) * 256.
        new("kp", "P gain", "duty/rad", "kp", c => 255.0 * 256.0 / c.CountsPerRad, c => c.Motor.Kp),
        new("current_limit", "current limit", "A", "current_limit", c => c.RawPerAmp, c => c.Motor.CurrentLimitA),
        new("speed_limit", "max speed", "deg/s", "speed_limit", c => c.CountsPerRad * Math.PI / 180, c => c.Motor.SpeedLimitRadS * 180 / Math.PI),
    ];

    /// <summary>Key in the API.</summary>
    public string Key { get; }

    /// <summary>What it is.</summary>
    public string Label { get; }

    /// <summary>Unit of the values.</summary>
    public string Unit { get; }

    /// <summary>The control-table field.</summary>
    public ControlTableField Field { get; }

    /// <summary>The parameter with <paramref name="key"/>, or null.</summary>
    public static MotorParameter? Find(string key) => All.FirstOrDefault(p => p.Key == key);

    /// <summary>The robot file's value for <paramref name="motor"/>.</summary>
    public double FileValue(MotorConfig motor) => _fileValue(motor);

    /// <summary>Module counts to robot units.</summary>
    public double FromCounts(MotorConfig motor, long counts) => counts / _countsPerUnit(motor);

    /// <summary>The range of values the field's type can hold, in robot units.</summary>
    public (double Min, double Max) Encodable(MotorConfig motor)
    {
        var (lo, hi) = TypeRange(Field);
        return (lo / _countsPerUnit(motor), hi / _countsPerUnit(motor));
    }

    /// <summary>Robot units to module counts; null (with the reason) when the value cannot be held by the field.</summary>
    public long? ToCounts(MotorConfig motor, double value, out string problem)
    {
        problem = string.Empty;
        if (!double.IsFinite(value))
        {
            problem = $"{Key} must be a finite number";
            return null;
        }

        var counts = Math.Round(value * _countsPerUnit(motor));
        var (lo, hi) = TypeRange(Field);
        if (counts < lo || counts > hi)
        {
            var (min, max) = Encodable(motor);
            problem = $"{Key} = {value:G6} {Unit} is {counts:F0} in the module's units, outside what {Field.Name} ({Field.Size * 8}-bit) holds: give {min:G4}..{max:G4} {Unit}";
            return null;
        }

        return (long)counts;
    }

    private static (double Lo, double Hi) TypeRange(ControlTableField field) =>
        field.Signed ? (-Math.Pow(2, (field.Size * 8) - 1), Math.Pow(2, (field.Size * 8) - 1) - 1) : (0, Math.Pow(2, field.Size * 8) - 1);
}
