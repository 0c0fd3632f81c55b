using RobotControl.Runtime.Discovery;

namespace RobotControl.WebConsole.Editor;

/// <summary>The plug-in types the editor offers, and the robot's node.</summary>
/// <param name="Types">Every type the catalog discovered (built-in and <c>--plugins</c> folders), by name.</param>
/// <param name="Robot">The robot node of a graph on <see cref="RobotFile"/>, or null when it cannot be read.</param>
/// <param name="RobotFile">The robot file as a graph in the folder names it.</param>
/// <param name="Problems">Assemblies or types the catalog could not load.</param>
public sealed record CatalogView(IReadOnlyList<PluginTypeView> Types, PluginPorts? Robot, string? RobotFile, IReadOnlyList<string> Problems);

/// <summary>One plug-in type.</summary>
/// <param name="Name">The name graph files use.</param>
/// <param name="Description">One-line description.</param>
/// <param name="Assembly">The assembly it comes from.</param>
/// <param name="Settings">Its settings schema (empty when it has none).</param>
/// <param name="Ports">Its inputs and outputs with default settings, or null when those cannot create it.</param>
/// <param name="PortsProblem">Why there are no ports (e.g. a required setting), else null.</param>
public sealed record PluginTypeView(string Name, string Description, string Assembly, IReadOnlyList<SettingDescription> Settings, PluginPorts? Ports, string? PortsProblem);

/// <summary>One problem the graph-file loader found, with its JSON path.</summary>
/// <param name="Path">JSON path, e.g. <c>$.wires[3].to</c>.</param>
/// <param name="Message">The loader's message.</param>
public sealed record ProblemView(string Path, string Message);

/// <summary>What the editor's Start and Stop act on.</summary>
/// <param name="Running">True while a session runs.</param>
/// <param name="Graph">The graph file it runs (null when stopped).</param>
/// <param name="Transport">The robot it runs on (virtual robot or the configured transport).</param>
/// <param name="Problem">Why the last start failed, else null.</param>
public sealed record RunView(bool Running, string? Graph, string Transport, string? Problem);

/// <summary>What a check of the edited graph found.</summary>
/// <param name="Problems">The loader's problems (empty: the graph loads and can run).</param>
/// <param name="Ports">The ports of each instance that could be created with its settings (and of <c>robot</c>).</param>
public sealed record CheckView(IReadOnlyList<ProblemView> Problems, IReadOnlyDictionary<string, PluginPorts> Ports);
