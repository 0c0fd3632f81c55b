using System.CommandLine;
using System.CommandLine.Parsing;
using System.Globalization;
using System.Numerics;
using System.Runtime.CompilerServices;
using RobotControl.Cli.Output;
using RobotControl.Host.Harness;

namespace RobotControl.Cli.Options;

/// <summary>
/// The one way <c>robotctl</c> makes options that take numbers, durations or output paths: each option checks its
/// value while the command line is parsed, before any command does anything, and a bad value gets one line naming the
/// option (e.g. <c>--speed-deg-s: 'NaN' is not a finite number from -720 to 720</c>). Every numeric option states its
/// range, which <see cref="RangeOf"/> exposes (the command-line tests feed every numeric option values inside and
/// outside it).
/// </summary>
internal static class CliOption
{
    private static readonly ConditionalWeakTable<Option, OptionRange> s_ranges = [];

    /// <summary>A number option with a default, accepted from <paramref name="min"/> to <paramref name="max"/> inclusive.</summary>
    public static Option<T> Number<T>(string name, string description, T min, T max, T defaultValue)
        where T : struct, INumber<T>
    {
        var option = new Option<T>(name)
        {
            Description = $"{description} [{Format(min)} to {Format(max)}; default {Format(defaultValue)}]",
            DefaultValueFactory = _ => defaultValue,
            CustomParser = result => ParseNumber(result, name, min, max),
        };
        s_ranges.Add(option, new OptionRange(double.CreateChecked(min), double.CreateChecked(max), typeof(T) == typeof(double)));
        return option;
    }

    /// <summary>An optional number option (null when not given), accepted from <paramref name="min"/> to <paramref name="max"/> inclusive.</summary>
    public static Option<T?> OptionalNumber<T>(string name, string description, T min, T max)
        where T : struct, INumber<T>
    {
        var option = new Option<T?>(name)
        {
            Description = $"{description} [{Format(min)} to {Format(max)}]",
            CustomParser = result => ParseNumber(result, name, min, max),
        };
        s_ranges.Add(option, new OptionRange(double.CreateChecked(min), double.CreateChecked(max), typeof(T) == typeof(double)));
        return option;
    }

    /// <summary>
    /// A duration option (<c>20s</c>, <c>500ms</c>, <c>2m</c>, or plain seconds), accepted from <paramref name="min"/>
    /// to <paramref name="max"/> inclusive.
    /// </summary>
    public static Option<TimeSpan> Duration(string name, string description, TimeSpan min, TimeSpan max, TimeSpan defaultValue)
    {
        var option = new Option<TimeSpan>(name)
        {
            Description = $"{description} [{Format(min)} to {Format(max)}; default {Format(defaultValue)}]",
            DefaultValueFactory = _ => defaultValue,
            CustomParser = result =>
            {
                var text = Single(result);
                TimeSpan value;
                try
                {
                    value = RunDuration.Parse(text);
                }
                catch (FormatException)
                {
                    result.AddError($"{name}: '{text}' is not a duration (e.g. 20s, 500ms, 2m) from {Format(min)} to {Format(max)}");
                    return default;
                }

                if (value < min || value > max)
                {
                    result.AddError($"{name}: '{text}' is outside {Format(min)} to {Format(max)}");
                }

                return value;
            },
        };
        s_ranges.Add(option, new OptionRange(min.TotalSeconds, max.TotalSeconds, true));
        return option;
    }

    /// <summary>An output file option: checked at parse time to be a file that can be written (see <see cref="OutputPath.CheckFile"/>).</summary>
    public static Option<FileInfo?> OutputFile(string name, string description)
    {
        var option = new Option<FileInfo?>(name) { Description = description };
        option.Validators.Add(result => Check(result, name, OutputPath.CheckFile));
        return option;
    }

    /// <summary>An output directory option: checked at parse time (see <see cref="OutputPath.CheckDirectory"/>).</summary>
    public static Option<DirectoryInfo> OutputDirectory(string name, string alias, string description)
    {
        var option = new Option<DirectoryInfo>(name, alias) { Description = description, Required = true };
        option.Validators.Add(result => Check(result, name, OutputPath.CheckDirectory));
        return option;
    }

    /// <summary>The range of an option made by <see cref="Number{T}"/>, <see cref="OptionalNumber{T}"/> or <see cref="Duration"/>; null for other options.</summary>
    public static OptionRange? RangeOf(Option option) => s_ranges.TryGetValue(option, out var range) ? range : null;

    private static T ParseNumber<T>(ArgumentResult result, string name, T min, T max)
        where T : struct, INumber<T>
    {
        var text = Single(result);
        var styles = typeof(T) == typeof(double) || typeof(T) == typeof(float) ? NumberStyles.Float : NumberStyles.Integer;
        var kind = styles == NumberStyles.Float ? "a finite number" : "a whole number";
        if (!T.TryParse(text, styles, CultureInfo.InvariantCulture, out var value) || !T.IsFinite(value))
        {
            result.AddError($"{name}: '{text}' is not {kind} from {Format(min)} to {Format(max)}");
            return default;
        }

        if (value < min || value > max)
        {
            result.AddError($"{name}: {text} is outside {Format(min)} to {Format(max)}");
        }

        return value;
    }

    private static string Single(ArgumentResult result) => result.Tokens.Count > 0 ? result.Tokens[^1].Value : string.Empty;

    private static void Check(OptionResult result, string name, Func<string, string?> check)
    {
        var token = result.Tokens.Count > 0 ? result.Tokens[^1].Value : null;
        if (token is null)
        {
            return;
        }

        if (string.IsNullOrWhiteSpace(token))
        {
            result.AddError($"{name}: the path is empty");
            return;
        }

        string full;
        try
        {
            full = Path.GetFullPath(token);
        }
        catch (Exception ex) when (ex is ArgumentException or NotSupportedException or PathTooLongException)
        {
            result.AddError($"{name}: '{token}' is not a usable path ({ex.Message})");
            return;
        }

        if (check(full) is { } problem)
        {
            result.AddError($"{name}: {problem}");
        }
    }

    private static string Format<T>(T value)
        where T : INumber<T> => value.ToString(null, CultureInfo.InvariantCulture);

    private static string Format(TimeSpan value) => value.TotalSeconds >= 1
        ? string.Create(CultureInfo.InvariantCulture, $"{value.TotalSeconds:0.###}s")
        : string.Create(CultureInfo.InvariantCulture, $"{value.TotalMilliseconds:0.###}ms");
}

/// <summary>The accepted range of a numeric option (durations in seconds).</summary>
/// <param name="Min">Smallest accepted value.</param>
/// <param name="Max">Largest accepted value.</param>
/// <param name="Fractional">True when fractions are accepted (a double or a duration).</param>
internal sealed record OptionRange(double Min, double Max, bool Fractional);
