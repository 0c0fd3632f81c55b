using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Robot;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// Describes the catalog for the editor's palette: each type's settings schema and the ports an instance with default
/// settings has on the robot (the editor draws a node with those). Creating such an instance opens no device and runs
/// no tick; it is disposed at once.
/// </summary>
internal static class EditorCatalog
{
    private const string ProbeName = "probe";

    public static CatalogView Describe(PluginCatalog catalog, GraphFolder folder, string? robotFile)
    {
        RobotDefinition? robot = null;
        NodePortsView? robotPorts = null;
        if (robotFile is not null)
        {
            try
            {
                robot = RobotLoader.Load(Path.Combine(folder.Root, robotFile));
                robotPorts = Ports(new RobotNode(robot, TimeProvider.System, folder.Root));
            }
            catch (RobotDataException)
            {
                robot = null; // the graph's own validation names the problem at $.robot
            }
        }

        var types = catalog.Types
            .OrderBy(t => t.Name, StringComparer.Ordinal)
            .Select(t => Describe(t, robot, folder.Root))
            .ToList();
        return new CatalogView(types, robotPorts, robotFile, catalog.Problems);
    }

    private static PluginTypeView Describe(PluginTypeInfo type, RobotDefinition? robot, string baseDirectory)
    {
        var settings = type.Settings?.Settings.Select(Setting).ToList() ?? [];
        NodePortsView? ports = null;
        string? problem = null;
        try
        {
            var context = new PluginContext(ProbeName, robot, TimeProvider.System, baseDirectory)
            {
                DeviceOpener = _ => throw new InvalidOperationException("the editor opens no device"),
            };
            var plugin = type.Create(null, context);
            ports = Ports(plugin);
            (plugin as IDisposable)?.Dispose();
        }
        catch (SettingsException ex)
        {
            problem = $"ports depend on settings: {string.Join("; ", ex.Errors.Select(e => $"{e.Path}: {e.Message}"))}";
        }
#pragma warning disable CA1031 // a plug-in constructor may fail in any way; the palette says so instead of failing
        catch (Exception ex)
#pragma warning restore CA1031
        {
            problem = $"ports depend on settings: {ex.Message}";
        }

        return new PluginTypeView(type.Name, type.Description, type.AssemblyName.Name ?? string.Empty, settings, ports, problem);
    }

    private static NodePortsView Ports(Plugin plugin) => new(
        [.. plugin.Inputs.Select(Port)],
        [.. plugin.Outputs.Select(Port)]);

    private static PortView Port(PortInfo p) => new(p.Name, p.Units, p.Description);

    private static SettingView Setting(SettingDescriptor s) => new(
        s.JsonName,
        s.Kind.ToString().ToLowerInvariant(),
        s.Description,
        s.Units,
        double.IsFinite(s.Minimum) ? s.Minimum : null,
        double.IsFinite(s.Maximum) ? s.Maximum : null,
        s.Required,
        s.DefaultValue is Enum e ? JsonNameOf(e, s) : s.DefaultValue,
        s.EnumNames,
        s.IsFilePath);

    private static string JsonNameOf(Enum value, SettingDescriptor s)
    {
        var index = Array.IndexOf(Enum.GetValues(value.GetType()), value);
        return index >= 0 && index < s.EnumNames.Count ? s.EnumNames[index] : value.ToString();
    }
}
