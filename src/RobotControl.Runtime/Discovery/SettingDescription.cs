using System.Text.Json;
using RobotControl.Plugins.Sdk.Settings;

namespace RobotControl.Runtime.Discovery;

/// <summary>One setting of a plug-in type's schema, as graph files write it.</summary>
/// <param name="Name">Graph-file (JSON) name.</param>
/// <param name="Kind">number, integer, boolean, text or choice.</param>
/// <param name="Units">Units (empty when none).</param>
/// <param name="Minimum">Lowest value (numbers; null when unbounded).</param>
/// <param name="Maximum">Highest value (numbers; null when unbounded).</param>
/// <param name="Default">The default as a graph file writes it (number, boolean, text or a choice's name; null when none).</param>
/// <param name="Choices">The names a choice takes (empty for other kinds).</param>
/// <param name="IsFilePath">True for a path relative to the graph file.</param>
/// <param name="Required">True when a graph must give it.</param>
/// <param name="Description">What it does.</param>
public sealed record SettingDescription(
    string Name,
    string Kind,
    string Units,
    double? Minimum,
    double? Maximum,
    object? Default,
    IReadOnlyList<string> Choices,
    bool IsFilePath,
    bool Required,
    string Description)
{
    /// <summary>Describes <paramref name="setting"/>.</summary>
    public static SettingDescription Of(SettingDescriptor setting)
    {
        ArgumentNullException.ThrowIfNull(setting);
        return new(
            setting.JsonName,
            JsonNamingPolicy.SnakeCaseLower.ConvertName(setting.Kind.ToString()),
            setting.Units,
            double.IsFinite(setting.Minimum) ? setting.Minimum : null,
            double.IsFinite(setting.Maximum) ? setting.Maximum : null,
            setting.DefaultValue is Enum e ? ChoiceName(e, setting) : setting.DefaultValue,
            setting.EnumNames,
            setting.IsFilePath,
            setting.Required,
            setting.Description);
    }

    /// <summary>The default as text (numbers in the invariant culture, booleans as <c>true</c>/<c>false</c>), or null when there is none.</summary>
    public string? FormatDefault() => Default switch
    {
        null => null,
        bool b => b ? "true" : "false",
        IFormattable f => f.ToString(null, System.Globalization.CultureInfo.InvariantCulture),
        var o => o.ToString(),
    };

    private static string ChoiceName(Enum value, SettingDescriptor setting)
    {
        var index = Array.IndexOf(Enum.GetValues(value.GetType()), value);
        return index >= 0 && index < setting.EnumNames.Count ? setting.EnumNames[index] : value.ToString();
    }
}
