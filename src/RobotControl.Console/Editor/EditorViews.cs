namespace RobotControl.WebConsole.Editor;

/// <summary>The plug-in types the editor offers, and the robot's node.</summary>
/// <param name="Types">Every type the catalog discovered (built-in and <c>--plugins</c> folders), by name.</param>
/// <param name="Robot">The robot node of a graph on <see cref="RobotFile"/>, or null when it cannot be read.</param>
/// <param name="RobotFile">The robot file as a graph in the folder names it.</param>
/// <param name="Problems">Assemblies or types the catalog could not load.</param>
public sealed record CatalogView(IReadOnlyList<PluginTypeView> Types, NodePortsView? Robot, string? RobotFile, IReadOnlyList<string> Problems);

/// <summary>One plug-in type.</summary>
/// <param name="Name">The name graph files use.</param>
/// <param name="Description">One-line description.</param>
/// <param name="Assembly">The assembly it comes from.</param>
/// <param name="Settings">Its settings schema (empty when it has none).</param>
/// <param name="Ports">Its inputs and outputs with default settings, or null when those cannot create it.</param>
/// <param name="PortsProblem">Why there are no ports (e.g. a required setting), else null.</param>
public sealed record PluginTypeView(string Name, string Description, string Assembly, IReadOnlyList<SettingView> Settings, NodePortsView? Ports, string? PortsProblem);

/// <summary>One setting of a schema.</summary>
/// <param name="Name">JSON name.</param>
/// <param name="Kind">number, integer, boolean, text or choice.</param>
/// <param name="Description">What it does.</param>
/// <param name="Units">Units (empty when none).</param>
/// <param name="Minimum">Lowest value (numbers; null when unbounded).</param>
/// <param name="Maximum">Highest value (numbers; null when unbounded).</param>
/// <param name="Required">True when a graph must give it.</param>
/// <param name="Default">The default value (null when none).</param>
/// <param name="Choices">The names a choice takes.</param>
/// <param name="IsFilePath">True for a path relative to the graph file.</param>
public sealed record SettingView(string Name, string Kind, string Description, string Units, double? Minimum, double? Maximum, bool Required, object? Default, IReadOnlyList<string> Choices, bool IsFilePath);

/// <summary>A node's inputs and outputs.</summary>
/// <param name="Inputs">Inputs in port order.</param>
/// <param name="Outputs">Outputs in port order.</param>
public sealed record NodePortsView(IReadOnlyList<PortView> Inputs, IReadOnlyList<PortView> Outputs);

/// <summary>One port.</summary>
/// <param name="Name">Port name (the signal is <c>instance.port</c>).</param>
/// <param name="Units">Units (empty when none).</param>
/// <param name="Description">What it carries.</param>
public sealed record PortView(string Name, string Units, string Description);

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
public sealed record CheckView(IReadOnlyList<ProblemView> Problems, IReadOnlyDictionary<string, NodePortsView> Ports);
