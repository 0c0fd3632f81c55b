using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Settings;
using SdkVersions = RobotControl.Plugins.Sdk.SdkVersion;

namespace RobotControl.Runtime.Discovery;

/// <summary>
/// What a plug-in type offers a graph: its settings schema and the ports of an instance. One description serves
/// <c>robotctl plugins</c>, the console's graph editor and <c>docs/plugin-reference.md</c>.
/// </summary>
/// <param name="Name">The name graph files use.</param>
/// <param name="Description">One-line description.</param>
/// <param name="TypeName">The plug-in class's full name.</param>
/// <param name="Assembly">The assembly it comes from.</param>
/// <param name="AssemblyVersion">That assembly's version.</param>
/// <param name="SdkVersion">The plug-in SDK version the assembly was built against.</param>
/// <param name="Location">Where the assembly was loaded from.</param>
/// <param name="Ports">The ports of an instance with the given settings, or null when creating one failed.</param>
/// <param name="PortsProblem">Why <paramref name="Ports"/> is null, else null.</param>
/// <param name="PortsFrom">Null when the ports are those of an instance with default settings; else the example
/// instance whose settings made them (<c>touch_right in teleop-lb.json</c>).</param>
/// <param name="Settings">The settings schema (empty when the type has no settings).</param>
public sealed record PluginDescription(
    string Name,
    string Description,
    string TypeName,
    string Assembly,
    string AssemblyVersion,
    string SdkVersion,
    string Location,
    PluginPorts? Ports,
    string? PortsProblem,
    IReadOnlyList<SettingDescription> Settings,
    string? PortsFrom = null)
{
    /// <summary>
    /// Describes <paramref name="type"/>. Ports are declared by the constructor, so an instance is created with
    /// default settings on <paramref name="robot"/> (if given) and disposed at once; it opens no device and runs no
    /// tick. When the defaults cannot make one and <paramref name="example"/> is given, its settings make it.
    /// </summary>
    public static PluginDescription Of(PluginTypeInfo type, RobotDefinition? robot, string baseDirectory, PluginExample? example = null)
    {
        ArgumentNullException.ThrowIfNull(type);
        var assembly = type.AssemblyName;
        string? from = null;
        if (!PluginPorts.TryCreate(type, null, robot, baseDirectory, out var ports, out var problem) && example is not null
            && PluginPorts.TryCreate(type, example.Settings, robot, example.BaseDirectory, out ports, out _))
        {
            (problem, from) = (null, $"{example.Instance} in {example.GraphFile}");
        }

        return new PluginDescription(
            type.Name,
            type.Description,
            type.Type.FullName ?? type.Type.Name,
            assembly.Name ?? string.Empty,
            assembly.Version is { } v ? SdkVersions.Format(v) : string.Empty,
            SdkVersions.Format(type.SdkVersion),
            type.AssemblyLocation,
            ports,
            problem,
            type.Settings is null ? [] : [.. type.Settings.Settings.Select(SettingDescription.Of)],
            from);
    }
}
