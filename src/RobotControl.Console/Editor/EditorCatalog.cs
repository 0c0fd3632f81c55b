using System.Text.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
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
    public static CatalogView Describe(PluginCatalog catalog, GraphFolder folder, string? robotFile)
    {
        RobotDefinition? robot = null;
        PluginPorts? robotPorts = null;
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
    public static Dictionary<string, PluginPorts> InstancePorts(LoadedGraph? loaded, JsonElement root, PluginCatalog catalog, RobotDefinition? robot, string baseDirectory)
    {
        var ports = new Dictionary<string, PluginPorts>(StringComparer.Ordinal);
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

        foreach (var (name, type, settings) in GraphInstances.Read(root, catalog))
        {
            if (PluginPorts.TryCreate(type, settings, robot, baseDirectory, out var found, out _))
            {
                ports[name] = found!;
            }
        }

        return ports;
    }

    private static PluginTypeView Describe(PluginTypeInfo type, RobotDefinition? robot, string baseDirectory)
    {
        var description = PluginDescription.Of(type, robot, baseDirectory);
        return new PluginTypeView(description.Name, description.Description, description.Assembly, description.Settings, description.Ports, description.PortsProblem);
    }

    private static PluginPorts Ports(Plugin plugin) => PluginPorts.Of(plugin);
}
