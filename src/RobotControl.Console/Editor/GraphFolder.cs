namespace RobotControl.WebConsole.Editor;

/// <summary>
/// The folder whose <c>*.json</c> graph files the editor lists, loads and saves (the folder of the graph the console
/// started with). Names are bare file names ending in <c>.json</c>: anything that would reach outside is refused.
/// </summary>
public sealed class GraphFolder
{
    /// <summary>The longest graph file name accepted.</summary>
    public const int MaxNameLength = 100;

    /// <summary>Serves the graphs in <paramref name="root"/>.</summary>
    public GraphFolder(string root)
    {
        ArgumentException.ThrowIfNullOrEmpty(root);
        Root = Path.GetFullPath(root);
    }

    /// <summary>The folder's full path.</summary>
    public string Root { get; }

    /// <summary>The graph files in the folder, by name.</summary>
    public IReadOnlyList<string> List() =>
        [.. Directory.EnumerateFiles(Root, "*.json").Select(Path.GetFileName).OfType<string>().Order(StringComparer.Ordinal)];

    /// <summary>The full path of graph <paramref name="name"/>, or null with why the name is refused.</summary>
    public string? Resolve(string? name, out string problem)
    {
        problem = string.Empty;
        if (string.IsNullOrWhiteSpace(name))
        {
            problem = "graph: give a file name, e.g. teleop-lb.json";
            return null;
        }

        if (name.Length > MaxNameLength)
        {
            problem = $"name: a graph file name has at most {MaxNameLength} characters (this one has {name.Length})";
            return null;
        }

        var full = Path.GetFullPath(Path.Combine(Root, name));
        if (name != Path.GetFileName(name) || name.StartsWith('.') || Path.GetDirectoryName(full) != Root.TrimEnd(Path.DirectorySeparatorChar))
        {
            problem = $"graph '{name}': only files directly in the graphs folder ({Path.GetFileName(Root)}/) can be loaded or saved";
            return null;
        }

        if (!name.EndsWith(".json", StringComparison.Ordinal))
        {
            problem = $"graph '{name}': a graph file name ends in .json";
            return null;
        }

        return full;
    }
}
