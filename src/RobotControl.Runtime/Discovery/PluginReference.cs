using System.Globalization;
using System.Text;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// The Markdown reference of plug-in types (<c>robotctl plugins --markdown</c>, kept as <c>docs/plugin-reference.md</c>):
/// one section per type with its inputs, outputs and settings. Tests compare the kept file with the code's own
/// description, so the reference cannot drift from what the plug-ins declare.
/// </summary>
public static class PluginReference
{
    /// <summary>
    /// The whole reference: a heading, how it is made, then <see cref="Section"/> of each type in the order given.
    /// <paramref name="robotName"/> names the robot the ports were taken on (null: none).
    /// </summary>
    public static string Document(IEnumerable<PluginDescription> plugins, string? robotName)
    {
        ArgumentNullException.ThrowIfNull(plugins);
        var list = plugins.ToList();
        var text = new StringBuilder();
        text.Append("# Plug-in reference\n\n");
        text.Append("The ").Append(list.Count).Append(" plug-in types the host ships, as they describe themselves: inputs and outputs (units, value before the\n");
        text.Append("first tick, and for an output the value it takes when its plug-in faults) and settings (kind, units, range, default).\n");
        text.Append(robotName is null
            ? "Ports that depend on the robot are not listed (no robot given).\n\n"
            : $"Ports that depend on the robot (one per joint, for example) are those on {robotName}.\n\n");
        text.Append("This file is written by the command below, never by hand; tests fail when it and the plug-ins disagree.\n\n");
        text.Append("    dotnet run --project src/RobotControl.Cli -- plugins --markdown --robot hardware/robots/lb-1.0.json --examples graphs/teleop-lb.json > docs/plugin-reference.md\n\n");
        foreach (var plugin in list)
        {
            text.Append(Section(plugin));
        }

        return text.ToString().TrimEnd('\n') + "\n";
    }

    /// <summary>The section of one type, from its <c>## name</c> heading to the blank line after its last table.</summary>
    public static string Section(PluginDescription plugin)
    {
        ArgumentNullException.ThrowIfNull(plugin);
        var text = new StringBuilder();
        text.Append("## ").Append(plugin.Name).Append("\n\n");
        text.Append(Cell(plugin.Description)).Append(" (`").Append(plugin.TypeName).Append("`, assembly `").Append(plugin.Assembly).Append("`)\n\n");
        if (plugin.Ports is null)
        {
            // The reason names local files (e.g. a missing default recording), so it stays out of a kept document.
            text.Append("Ports: declared from its settings when created; with the defaults it cannot be created (`robotctl plugins` says why), so they are not listed.\n\n");
        }
        else
        {
            if (plugin.PortsFrom is { } from)
            {
                text.Append("Ports of an instance with the settings of ").Append(Cell(from)).Append(" (the defaults cannot make one):\n\n");
            }

            Table(text, ["input", "units", "initial", "description"], plugin.Ports.Inputs.Select(p => new[] { Code(p.Name), p.Units, Number(p.InitialValue), p.Description }));
            Table(text, ["output", "units", "initial", "safe value", "description"], plugin.Ports.Outputs.Select(p => new[] { Code(p.Name), p.Units, Number(p.InitialValue), p.SafeValue ?? string.Empty, p.Description }));
        }

        Table(text, ["setting", "kind", "units", "range", "default", "description"], plugin.Settings.Select(s => new[] { Code(s.Name), s.Kind, s.Units, Range(s), Default(s), s.Description }));
        return text.ToString();
    }

    private static void Table(StringBuilder text, string[] header, IEnumerable<string[]> rows)
    {
        var list = rows.ToList();
        if (list.Count == 0)
        {
            text.Append("No ").Append(header[0]).Append("s.\n\n");
            return;
        }

        text.Append("| ").Append(string.Join(" | ", header)).Append(" |\n|");
        text.Append(string.Concat(Enumerable.Repeat("---|", header.Length))).Append('\n');
        foreach (var row in list)
        {
            text.Append("| ").Append(string.Join(" | ", row.Select(Cell))).Append(" |\n");
        }

        text.Append('\n');
    }

    private static string Range(SettingDescription s)
    {
        if (s.Choices.Count > 0)
        {
            return string.Join(", ", s.Choices.Select(Code));
        }

        return s.Minimum is null && s.Maximum is null
            ? string.Empty
            : $"{(s.Minimum is { } min ? Number(min) : "−∞")} … {(s.Maximum is { } max ? Number(max) : "∞")}";
    }

    private static string Default(SettingDescription s) => s.Default switch
    {
        null => s.Required ? "(required)" : string.Empty,
        string t => t.Length == 0 ? "\"\"" : Code(t),
        _ => s.FormatDefault() ?? string.Empty,
    };

    private static string Number(double value) => value.ToString("R", CultureInfo.InvariantCulture);

    private static string Code(string text) => $"`{text}`";

    private static string Cell(string text) => text.Replace("|", "\\|", StringComparison.Ordinal).Replace("\n", " ", StringComparison.Ordinal);
}
