using System.Text.Json;
using RobotControl.Hardware.Model;
using RobotControl.Plugins.Sdk;
using SdkVersions = RobotControl.Plugins.Sdk.SdkVersion;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Cli.Commands.Plugins;

/// <summary>What <c>robotctl plugins</c> reports about one plug-in type (also its <c>--json</c> form).</summary>
internal sealed record PluginListing(
    string Name,
    string Description,
    string Type,
    string Assembly,
    string AssemblyVersion,
    string SdkVersion,
    string Location,
    IReadOnlyList<PortListing>? Inputs,
    IReadOnlyList<PortListing>? Outputs,
    string? PortsNote,
    IReadOnlyList<SettingListing> Settings)
{
    /// <summary>
    /// Describes <paramref name="info"/>. Ports are declared by the constructor, so an instance is created with
    /// default settings (and <paramref name="robot"/>, if given); when that fails the ports are null and
    /// <see cref="PortsNote"/> says why.
    /// </summary>
    public static PluginListing Of(PluginTypeInfo info, RobotDefinition? robot)
    {
        IReadOnlyList<PortListing>? inputs = null;
        IReadOnlyList<PortListing>? outputs = null;
        string? note = null;
        try
        {
            var plugin = info.Create(null, PluginContext.Standalone(info.Name, robot));
            inputs = [.. plugin.Inputs.Select(p => PortListing.Of(p, isOutput: false))];
            outputs = [.. plugin.Outputs.Select(p => PortListing.Of(p, isOutput: true))];
            (plugin as IDisposable)?.Dispose();
        }
        catch (Exception ex) when (ex is not OutOfMemoryException)
        {
            note = $"declared when created; with default settings{(robot is null ? " and no robot" : "")}: {ex.Message}";
        }

        var assembly = info.AssemblyName;
        return new PluginListing(
            info.Name,
            info.Description,
            info.Type.FullName ?? info.Type.Name,
            assembly.Name ?? "",
            assembly.Version is { } v ? SdkVersions.Format(v) : "",
            SdkVersions.Format(info.SdkVersion),
            info.AssemblyLocation,
            inputs,
            outputs,
            note,
            info.Settings is null ? [] : [.. info.Settings.Settings.Select(SettingListing.Of)]);
    }
}

/// <summary>One input or output.</summary>
internal sealed record PortListing(string Name, string Units, string Description, double InitialValue, string? SafeValue)
{
    public static PortListing Of(PortInfo port, bool isOutput) =>
        new(port.Name, port.Units, port.Description, port.InitialValue, isOutput ? JsonNamingPolicy.SnakeCaseLower.ConvertName(port.SafeValue.ToString()) : null);
}

/// <summary>One setting: graph-file name, kind, units, range (null: unbounded), default and help.</summary>
internal sealed record SettingListing(
    string Name,
    string Kind,
    string Units,
    double? Minimum,
    double? Maximum,
    string? Default,
    IReadOnlyList<string> Choices,
    bool IsFilePath,
    bool Required,
    string Description)
{
    public static SettingListing Of(SettingDescriptor s) => new(
        s.JsonName,
        JsonNamingPolicy.SnakeCaseLower.ConvertName(s.Kind.ToString()),
        s.Units,
        double.IsNaN(s.Minimum) ? null : s.Minimum,
        double.IsNaN(s.Maximum) ? null : s.Maximum,
        s.DefaultValue switch
        {
            null => null,
            Enum e => JsonNamingPolicy.SnakeCaseLower.ConvertName(e.ToString()),
            bool b => b ? "true" : "false",
            IFormattable f => f.ToString(null, System.Globalization.CultureInfo.InvariantCulture),
            var o => o.ToString(),
        },
        s.EnumNames,
        s.IsFilePath,
        s.Required,
        s.Description);
}
