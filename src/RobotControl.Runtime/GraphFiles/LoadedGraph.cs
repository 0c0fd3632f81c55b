using RobotControl.Definitions.Model;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Robot;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>A graph file loaded and checked: its document, robot, instances wired together and compiled.</summary>
/// <param name="Path">Full path of the graph file.</param>
/// <param name="Document">What the file says (save it to write the file back).</param>
/// <param name="Robot">The robot, when the file names one.</param>
/// <param name="RobotNode">The robot's node (instance <c>robot</c>), when the file names a robot; attach a port before running.</param>
/// <param name="Graph">The instances and wires.</param>
/// <param name="Program">The compiled graph.</param>
public sealed record LoadedGraph(
    string Path,
    GraphDocument Document,
    RobotDefinition? Robot,
    RobotNode? RobotNode,
    PluginGraph Graph,
    GraphProgram Program);
