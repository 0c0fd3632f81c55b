using System.Text.Json.Nodes;

namespace RobotControl.Bench.EStop;

/// <summary>
/// The graph and its robot file as the benchmark runs them: copies, next to the originals (so that their relative
/// references still hold), whose robot file sets the operator check's safe state (<c>safety.safe_state.operator</c>:
/// <c>hold</c> or <c>torque_off</c>) and whose graph names that robot file. Deleted on dispose.
/// </summary>
internal sealed class EStopRobotFiles : IDisposable
{
    private EStopRobotFiles(string graph, string robot)
    {
        Graph = graph;
        Robot = robot;
    }

    /// <summary>The graph copy to open.</summary>
    public string Graph { get; }

    /// <summary>The robot file copy it names.</summary>
    public string Robot { get; }

    /// <summary>Writes the copies of <paramref name="graphPath"/> and its robot file with the operator's <paramref name="safeState"/>.</summary>
    /// <exception cref="InvalidOperationException">The graph names no robot file.</exception>
    public static EStopRobotFiles Write(string graphPath, string safeState)
    {
        var graphFull = Path.GetFullPath(graphPath);
        var graph = JsonNode.Parse(File.ReadAllText(graphFull))!.AsObject();
        var robotRef = graph["robot"]?.GetValue<string>() ?? throw new InvalidOperationException($"{graphPath} names no robot file");
        var robotFull = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(graphFull)!, robotRef));
        var robot = JsonNode.Parse(File.ReadAllText(robotFull))!.AsObject();
        var safety = robot["safety"] as JsonObject ?? [];
        robot["safety"] = safety;
        var states = safety["safe_state"] as JsonObject ?? [];
        safety["safe_state"] = states;
        states["operator"] = safeState;
        var stamp = $".estop-bench-{Environment.ProcessId}";
        var robotCopy = Path.Combine(Path.GetDirectoryName(robotFull)!, $"{stamp}-{Path.GetFileName(robotFull)}");
        var graphCopy = Path.Combine(Path.GetDirectoryName(graphFull)!, $"{stamp}-{Path.GetFileName(graphFull)}");
        graph["robot"] = Path.GetRelativePath(Path.GetDirectoryName(graphFull)!, robotCopy).Replace('\\', '/');
        File.WriteAllText(robotCopy, robot.ToJsonString());
        File.WriteAllText(graphCopy, graph.ToJsonString());
        return new EStopRobotFiles(graphCopy, robotCopy);
    }

    public void Dispose()
    {
        File.Delete(Graph);
        File.Delete(Robot);
    }
}
