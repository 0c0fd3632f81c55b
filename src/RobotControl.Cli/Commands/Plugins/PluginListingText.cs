using System.Globalization;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Cli.Commands.Plugins;

/// <summary>The human-readable form of <c>robotctl plugins</c>: one block per type, aligned columns per section.</summary>
internal static class PluginListingText
{
    public static void Write(IReadOnlyList<PluginDescription> listings, TextWriter output)
    {
        output.WriteLine($"{listings.Count} plug-in types (host plug-in SDK {RobotControl.Plugins.Sdk.SdkVersion.Text})");
        foreach (var p in listings)
        {
            output.WriteLine();
            output.WriteLine($"{p.Name}  {p.Description}");
            output.WriteLine($"  assembly  {p.Assembly} {p.AssemblyVersion}, built against SDK {p.SdkVersion}  ({p.Location})");
            if (p.Ports is null)
            {
                output.WriteLine($"  ports     {p.PortsProblem}");
            }
            else
            {
                Section(output, "inputs", p.Ports.Inputs.Select(i => new[] { i.Name, Units(i.Units), i.Description }));
                Section(output, "outputs", p.Ports.Outputs.Select(o => new[] { o.Name, Units(o.Units), o.Description, $"(safe: {o.SafeValue})" }));
            }

            Section(output, "settings", p.Settings.Select(s => new[] { s.Name, s.Kind, Units(s.Units), Range(s), $"default {s.FormatDefault() ?? "-"}", s.Description }));
        }
    }

    private static void Section(TextWriter output, string title, IEnumerable<string[]> rows)
    {
        var table = rows.ToList();
        if (table.Count == 0)
        {
            output.WriteLine($"  {title,-9} (none)");
            return;
        }

        var widths = Enumerable.Range(0, table.Max(r => r.Length))
            .Select(c => table.Max(r => c < r.Length ? r[c].Length : 0))
            .ToArray();
        for (var i = 0; i < table.Count; i++)
        {
            var cells = table[i].Select((cell, c) => c == table[i].Length - 1 ? cell : cell.PadRight(widths[c]));
            output.WriteLine($"  {(i == 0 ? title : ""),-9} {string.Join("  ", cells).TrimEnd()}");
        }
    }

    private static string Units(string units) => units.Length == 0 ? "" : $"[{units}]";

    private static string Range(SettingDescription s)
    {
        if (s.Choices.Count > 0)
        {
            return "{" + string.Join('|', s.Choices) + "}";
        }

        if (s.Minimum is null && s.Maximum is null)
        {
            return "";
        }

        var c = CultureInfo.InvariantCulture;
        return string.Create(c, $"{(s.Minimum is { } min ? min.ToString(c) : "-inf")} .. {(s.Maximum is { } max ? max.ToString(c) : "inf")}");
    }
}
