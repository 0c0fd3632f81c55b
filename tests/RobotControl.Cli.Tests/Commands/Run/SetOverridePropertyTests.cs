using System.Globalization;
using RobotControl.Definitions.Json;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>
/// Issue 29, class 7: a property test of <c>robotctl run --set instance.setting=value</c> on the shipped teleop graph,
/// seeded. Every bad override (malformed, an unknown instance or setting, a value its setting cannot take: NaN,
/// ±Infinity, huge or out-of-range numbers, empty, unicode, JSON fragments, control characters) is refused before the
/// run starts, with a non-zero exit and exactly one line on stderr naming the --set, and no stack trace; every good one
/// (a value inside its setting's range) is applied by the graph loader as the file's own value would be. The bad ones go
/// through the real command in-process (the graph is loaded before anything else, so a refusal costs no session); the
/// good ones through the loader the command uses (<see cref="GraphFile.Load(string, PluginCatalog, TimeProvider, IReadOnlyList{SettingOverride})"/>),
/// which needs no run.
/// </summary>
public sealed class SetOverridePropertyTests
{
    private const int Cases = 300;
    private static readonly string Graph = Cli.RepoFile("graphs/teleop-lb.json");
    private static readonly PluginCatalog Catalog = ShippedPlugins.Catalog();
    private static readonly string[] Junk =
    [
        "NaN", "nan", "Infinity", "-Infinity", "+Infinity", "∞", "1e400", "-1e400", "1e999999", "", " ", "\t", "٣", "１２", "½",
        "{\"a\": 1}", "[1, 2]", "null", "true", "\"0.5\"", "0x10", "1,5", "1.2.3", "--", "=", "x=1", "Ωμέγα", "🤖", "\u0007", "a\nb", "é\u0301",
    ];

    [Fact]
    public void Every_bad_override_is_one_line_naming_the_set_with_no_stack_trace_and_a_non_zero_exit()
    {
        var random = new Random(29);
        var instances = Instances();
        for (var i = 0; i < Cases; i++)
        {
            var text = BadOverride(random, instances);

            var (code, _, error) = Cli.Run("run", Graph, "--virtual", "--duration", "0.01s", "--set", text);

            var lines = error.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
            var shown = JsonProblem.OneLine(text);
            Assert.True(code != 0, $"--set {shown}: exit 0");
            Assert.True(lines.Length == 1, $"--set {shown}: expected one line, got:\n{error}");
            Assert.Contains("--set", lines[0], StringComparison.Ordinal);
            Assert.DoesNotContain("   at ", error, StringComparison.Ordinal);
            Assert.DoesNotContain("Exception", error, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void Every_good_override_is_applied_as_the_files_own_value_would_be()
    {
        var random = new Random(29);
        var instances = Instances();
        var settable = instances.SelectMany(x => x.Settings.Where(s => Good(random, s) is not null).Select(s => (x.Name, Setting: s))).ToList();
        Assert.NotEmpty(settable);
        for (var i = 0; i < Cases; i++)
        {
            var (name, setting) = settable[random.Next(settable.Count)];
            var (text, expected) = Good(random, setting)!.Value;

            var loaded = GraphFile.Load(Graph, Catalog, TimeProvider.System, [SettingOverride.Parse($"{name}.{setting.JsonName}={text}")]);

            var settings = loaded.Document.Instances.Single(x => x.Name == name).Settings!;
            Assert.Equal(expected, setting.Property.GetValue(settings));
        }
    }

    /// <summary>The graph's instances and the settings their types declare.</summary>
    private static List<(string Name, IReadOnlyList<SettingDescriptor> Settings)> Instances()
    {
        var document = GraphFile.Load(Graph, Catalog, TimeProvider.System).Document;
        return [.. document.Instances.Select(x => (x.Name, Catalog.Find(x.Type)?.Settings?.Settings ?? (IReadOnlyList<SettingDescriptor>)[]))];
    }

    /// <summary>An override that must be refused, of one of five kinds.</summary>
    private static string BadOverride(Random random, List<(string Name, IReadOnlyList<SettingDescriptor> Settings)> instances)
    {
        var names = instances.Select(x => x.Name).ToHashSet(StringComparer.Ordinal);
        var (instance, settings) = instances[random.Next(instances.Count)];
        switch (random.Next(5))
        {
            case 0: // malformed: no '=', no '.', or an empty instance or setting
                var word = Word(random);
                return random.Next(4) switch
                {
                    0 => $"{instance}.{word}",
                    1 => $"{word}={Pick(random, Junk)}",
                    2 => $".{word}={Pick(random, Junk)}",
                    _ => $"{instance}.={Pick(random, Junk)}",
                };
            case 1: // an instance the graph does not have
                string other;
                do
                {
                    other = Word(random);
                }
                while (names.Contains(other));
                return $"{other}.{Word(random)}={Pick(random, Junk)}";
            case 2: // a setting the instance's type does not have
                string setting;
                do
                {
                    setting = Word(random);
                }
                while (settings.Any(s => s.JsonName == setting));
                return $"{instance}.{setting}={Pick(random, Junk)}";
            default: // a value its setting cannot take
                var typed = instances.Where(x => x.Settings.Any(s => Bad(random, s) is not null)).ToList();
                var (owner, ownSettings) = typed[random.Next(typed.Count)];
                var candidates = ownSettings.Where(s => Bad(random, s) is not null).ToList();
                var target = candidates[random.Next(candidates.Count)];
                return $"{owner}.{target.JsonName}={Bad(random, target)}";
        }
    }

    /// <summary>A value <paramref name="setting"/> cannot take, or null when the test has none for its kind.</summary>
    private static string? Bad(Random random, SettingDescriptor setting)
    {
        string[] nonNumbers = [.. Junk.Where(j => !double.TryParse(j.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out var d) || !double.IsFinite(d))];
        switch (setting.Kind)
        {
            case SettingKind.Number when random.Next(2) == 0 && double.IsFinite(setting.Maximum):
                return (setting.Maximum + (Math.Abs(setting.Maximum) + 1) * Math.Pow(10, random.Next(0, 300))).ToString("R", CultureInfo.InvariantCulture);
            case SettingKind.Number when random.Next(2) == 0 && double.IsFinite(setting.Minimum):
                return (setting.Minimum - (Math.Abs(setting.Minimum) + 1) * Math.Pow(10, random.Next(0, 300))).ToString("R", CultureInfo.InvariantCulture);
            case SettingKind.Number:
            case SettingKind.Integer:
                return Pick(random, nonNumbers);
            case SettingKind.Boolean:
                string b;
                do
                {
                    b = Pick(random, Junk);
                }
                while (bool.TryParse(b, out _));
                return b;
            case SettingKind.Text when setting.Required:
                return random.Next(2) == 0 ? string.Empty : " ";
            case SettingKind.Choice:
                return Word(random) + "!";
            default:
                return null;
        }
    }

    /// <summary>A value <paramref name="setting"/> takes, as typed and as the settings object then holds it; null when the test has none.</summary>
    private static (string Text, object Expected)? Good(Random random, SettingDescriptor setting)
    {
        switch (setting.Kind)
        {
            case SettingKind.Number when double.IsFinite(setting.Minimum) && double.IsFinite(setting.Maximum):
                var v = setting.Minimum + (random.NextDouble() * (setting.Maximum - setting.Minimum));
                var text = v.ToString("R", CultureInfo.InvariantCulture);
                return (random.Next(2) == 0 ? text : $" {text} ", double.Parse(text, CultureInfo.InvariantCulture));
            case SettingKind.Boolean:
                var on = random.Next(2) == 0;
                return (random.Next(2) == 0 ? on.ToString(CultureInfo.InvariantCulture).ToUpperInvariant() : on ? "true" : "false", on);
            default:
                return null;
        }
    }

    /// <summary>A name of 1 to 12 characters: letters, digits, '_', unicode, a space or a control character (never '=' or '.').</summary>
    private static string Word(Random random)
    {
        const string alphabet = "abcxyz_019ÄßΩж漢🙂 \t\u0007-+:/";
        var chars = new List<string>();
        var length = random.Next(1, 13);
        var e = System.Globalization.StringInfo.GetTextElementEnumerator(alphabet);
        var elements = new List<string>();
        while (e.MoveNext())
        {
            elements.Add((string)e.Current);
        }

        for (var i = 0; i < length; i++)
        {
            chars.Add(elements[random.Next(elements.Count)]);
        }

        var word = string.Concat(chars).Trim();
        return word.Length == 0 ? "q" : word;
    }

    private static string Pick(Random random, string[] values) => values[random.Next(values.Length)];
}
