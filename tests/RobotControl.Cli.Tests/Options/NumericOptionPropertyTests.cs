using System.CommandLine;
using System.Globalization;
using RobotControl.Cli.Options;

namespace RobotControl.Cli.Tests.Options;

/// <summary>
/// Every numeric option of every command (found in the command tree, so new options are covered) gets random values:
/// NaN, infinities, huge, negative, non-numbers, the bounds and random values inside and outside its range. A value
/// outside the range must be refused while parsing (no command runs) with one line naming the option and a non-zero
/// exit; a value inside must parse. Values inside are not run here: each command's own tests run it, and running
/// every random value would cost minutes of virtual-robot time.
/// </summary>
public sealed class NumericOptionPropertyTests
{
    private static readonly Type[] NumericTypes = [typeof(int), typeof(long), typeof(double), typeof(float), typeof(decimal), typeof(short), typeof(byte), typeof(uint), typeof(ulong), typeof(TimeSpan)];

    private static readonly string[] Hostile =
    [
        "NaN", "nan", "Infinity", "-Infinity", "∞", "-∞", "1e308", "-1e308", "1e400", "-1e400", "9999999999999999999999",
        "-9999999999999999999999", "-1", "-0.5", "0", "abc", "", " ", "0x10", "1,5", "1.5.2", "1e", "--", "5s", "2m", "-1ms",
    ];

    [Fact]
    public void Every_numeric_option_is_made_with_a_range()
    {
        var unranged = NumericOptions().Where(o => CliOption.RangeOf(o.Option) is null).Select(o => $"{string.Join(' ', o.Path)} {o.Option.Name}").ToArray();

        Assert.NotEmpty(NumericOptions());
        Assert.True(unranged.Length == 0, "numeric options without a range (make them with CliOption): " + string.Join(", ", unranged));
    }

    [Fact]
    public void Random_values_either_parse_inside_the_range_or_are_refused_in_one_line_naming_the_option()
    {
        var random = new Random(18);
        var checkedValues = 0;
        foreach (var (path, command, option) in NumericOptions())
        {
            var range = CliOption.RangeOf(option)!;
            foreach (var value in Hostile.Concat(Generated(range, random)))
            {
                var args = path.Concat(RequiredInputs(command)).Concat([option.Name, value]).ToArray();
                var parse = CliApp.BuildRoot().Parse(args);
                var errors = parse.Errors.Where(e => e.Message.Contains(option.Name, StringComparison.Ordinal)).ToArray();
                if (Accepts(range, option.ValueType, value))
                {
                    Assert.True(parse.Errors.Count == 0, $"{string.Join(' ', args)}: refused a value inside [{range.Min}, {range.Max}]: {string.Join("; ", parse.Errors.Select(e => e.Message))}");
                }
                else
                {
                    Assert.True(errors.Length > 0, $"{string.Join(' ', args)}: accepted a value outside [{range.Min}, {range.Max}] at parse time");
                    Cli.AssertRefused(Cli.Run(args), option.Name);
                }

                checkedValues++;
            }
        }

        Assert.True(checkedValues > 200, $"only {checkedValues} values checked");
    }

    /// <summary>Bounds, just outside them, and random values inside and far outside.</summary>
    private static IEnumerable<string> Generated(OptionRange range, Random random)
    {
        var c = CultureInfo.InvariantCulture;
        var span = Math.Min(range.Max - range.Min, 1e12);
        var step = range.Fractional ? Math.Max(span * 1e-6, 1e-3) : 1;
        yield return range.Min.ToString("R", c);
        yield return Math.Min(range.Max, 1e15).ToString("R", c);
        if (range.Min > -1e15)
        {
            yield return (range.Min - step).ToString("R", c);
        }

        if (range.Max < 1e15)
        {
            yield return (range.Max + step).ToString("R", c);
        }

        for (var i = 0; i < 8; i++)
        {
            var inside = range.Min + (random.NextDouble() * span);
            yield return range.Fractional ? inside.ToString("R", c) : Math.Floor(inside).ToString("F0", c);
            yield return ((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(0, 30))).ToString("R", c);
        }
    }

    /// <summary>The property's oracle: a finite number (whole for integer options) within the range.</summary>
    private static bool Accepts(OptionRange range, Type type, string text)
    {
        var t = text.Trim();
        var scale = 1.0;
        if ((Nullable.GetUnderlyingType(type) ?? type) == typeof(TimeSpan))
        {
            (t, scale) = t.EndsWith("ms", StringComparison.Ordinal) ? (t[..^2], 1e-3) : t.EndsWith('s') ? (t[..^1], 1.0) : t.EndsWith('m') ? (t[..^1], 60.0) : (t, 1.0);
        }

        if (text.Length == 0 || !double.TryParse(t, NumberStyles.Float, CultureInfo.InvariantCulture, out var value) || !double.IsFinite(value))
        {
            return false;
        }

        if (!range.Fractional && (value != Math.Floor(value) || t.Contains('.', StringComparison.Ordinal) || t.Contains('e', StringComparison.OrdinalIgnoreCase)))
        {
            return false;
        }

        value *= scale;
        return value >= range.Min && value <= range.Max;
    }

    /// <summary>Values for every argument and required option, so that only the option under test can fail.</summary>
    private static IEnumerable<string> RequiredInputs(Command command)
    {
        foreach (var argument in command.Arguments)
        {
            yield return argument.Name switch
            {
                "transport" => "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json"),
                "robot" => Cli.RepoFile("hardware/robots/lb-1.0.json"),
                "graph" => Cli.RepoFile("graphs/teleop-lb.json"),
                _ => throw new InvalidOperationException($"{command.Name}: no sample value for argument '{argument.Name}'; add one here"),
            };
        }

        foreach (var option in command.Options.Where(o => o.Required))
        {
            yield return option.Name;
            yield return option.Name switch
            {
                "--motor" => "right.elbow",
                "--transport" => "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json"),
                "--unit" => "property-test-unit",
                "--out" => Path.Combine(Path.GetTempPath(), "rc-never-written"),
                _ => throw new InvalidOperationException($"{command.Name}: no sample value for required option '{option.Name}'; add one here"),
            };
        }
    }

    private static List<(string[] Path, Command Command, Option Option)> NumericOptions()
    {
        var result = new List<(string[], Command, Option)>();
        void Walk(Command command, string[] path)
        {
            foreach (var option in command.Options.Where(o => NumericTypes.Contains(Nullable.GetUnderlyingType(o.ValueType) ?? o.ValueType)))
            {
                result.Add((path, command, option));
            }

            foreach (var sub in command.Subcommands)
            {
                Walk(sub, [.. path, sub.Name]);
            }
        }

        Walk(CliApp.BuildRoot(), []);
        return result;
    }
}
