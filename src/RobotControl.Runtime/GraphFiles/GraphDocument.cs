using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Runtime.Graph;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>
/// A graph file's content: the robot file, the transport to it, the loop rate, plug-in instances with their settings,
/// and wires. Paths are kept as written (relative to the graph file's folder).
/// </summary>
/// <param name="Robot">Robot file as written, or null for a graph without a robot.</param>
/// <param name="Transport">Transport to the robot, e.g. <c>virtual</c> or <c>serial:/dev/ttyUSB0?baud=1000000</c>.</param>
/// <param name="LoopRateHz">Control-loop rate.</param>
/// <param name="Instances">Plug-in instances.</param>
/// <param name="Wires">Wires, in file order.</param>
public sealed record GraphDocument(
    string? Robot,
    string Transport,
    double LoopRateHz,
    IReadOnlyList<InstanceSpec> Instances,
    IReadOnlyList<Wire> Wires)
{
    /// <summary>The schema identifier graph files carry.</summary>
    public const string Schema = "robotcontrol/graph/1";

    /// <summary>The graph editor's node positions by instance name (editor-only; null: none).</summary>
    public IReadOnlyDictionary<string, NodePosition>? Layout { get; init; }

    /// <summary>The default loop rate.</summary>
    public const double DefaultLoopRateHz = 1000.0;
}

/// <summary>One plug-in instance in a graph file.</summary>
/// <param name="Name">Instance name.</param>
/// <param name="Type">Plug-in type name.</param>
/// <param name="Settings">Validated settings (null for a type without settings).</param>
public sealed record InstanceSpec(string Name, string Type, PluginSettings? Settings)
{
    /// <summary>
    /// The settings the file gave by name (even at their defaults), or null when it had no <c>settings</c> object:
    /// written back so when the file is saved. How the file was written, not what the graph is: equality leaves it out.
    /// </summary>
    public IReadOnlyList<string>? Written { get; init; }

    /// <inheritdoc />
    public bool Equals(InstanceSpec? other) =>
        other is not null && Name == other.Name && Type == other.Type && Equals(Settings, other.Settings);

    /// <inheritdoc />
    public override int GetHashCode() => HashCode.Combine(Name, Type, Settings);
}
