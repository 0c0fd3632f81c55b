using System.Text.Json;
using RobotControl.Hardware.Json;
using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
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

    /// <summary>
    /// The ports of each instance of a loaded graph's text whose settings read cleanly (a type's ports may depend on
    /// its settings: the touch's on its back end, the playback's on its file). Problems are the loader's to report.
    /// </summary>
    public static Dictionary<string, NodePortsView> InstancePorts(LoadedGraph? loaded, JsonElement root, PluginCatalog catalog, RobotDefinition? robot, string baseDirectory)
    {
        var ports = new Dictionary<string, NodePortsView>(StringComparer.Ordinal);
        if (loaded is not null)
        {
            foreach (var plugin in loaded.Graph.Instances)
            {
                ports[plugin.Name] = Ports(plugin);
            }

            return ports;
        }

        if (robot is not null)
        {
            ports[RobotNode.InstanceName] = Ports(new RobotNode(robot, TimeProvider.System, baseDirectory));
        }

        if (!root.TryGetProperty("instances", out var instances) || instances.ValueKind != JsonValueKind.Array)
        {
            return ports;
        }

        foreach (var item in instances.EnumerateArray())
        {
            if (item.ValueKind != JsonValueKind.Object || !item.TryGetProperty("name", out var n) || n.ValueKind != JsonValueKind.String
                || !item.TryGetProperty("type", out var t) || t.ValueKind != JsonValueKind.String || catalog.Find(t.GetString()!) is not { } type)
            {
                continue;
            }

            var errors = new List<JsonProblem>();
            var settings = type.Settings?.Read(item.TryGetProperty("settings", out var s) ? s : default, errors);
            if (errors.Count == 0 && TryPorts(type, settings, robot, baseDirectory, out var found, out _))
            {
                ports[n.GetString()!] = found!;
            }
        }

        return ports;
    }

    private static bool TryPorts(PluginTypeInfo type, PluginSettings? settings, RobotDefinition? robot, string baseDirectory, out NodePortsView? ports, out string? problem)
    {
        ports = null;
        problem = null;
        try
        {
            var context = new PluginContext(ProbeName, robot, TimeProvider.System, baseDirectory)
            {
                DeviceOpener = _ => throw new InvalidOperationException("the editor opens no device"),
            };
            var plugin = type.Create(settings, context);
            ports = Ports(plugin);
            (plugin as IDisposable)?.Dispose();
            return true;
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

        return false;
    }

    private static PluginTypeView Describe(PluginTypeInfo type, RobotDefinition? robot, string baseDirectory)
    {
        var settings = type.Settings?.Settings.Select(Setting).ToList() ?? [];
        TryPorts(type, null, robot, baseDirectory, out var ports, out var problem);
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
