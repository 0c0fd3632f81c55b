using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// The graph editor's server side: the palette (<see cref="EditorCatalog"/>), checking a graph with the graph-file
/// loader itself (<see cref="GraphFile.LoadFromText"/>: the same problems, messages and JSON paths as
/// <c>robotctl run</c>), loading and saving the folder's graph files with <see cref="GraphFile"/>'s writer, and
/// running the edited graph in place of the console's session (<see cref="GraphRunner"/>).
/// </summary>
public sealed class GraphEditor
{
    /// <summary>The name an unsaved graph is checked under (its relative paths resolve in the folder).</summary>
    public const string UntitledName = "untitled.json";

    private readonly PluginCatalog _catalog;

    /// <summary>Edits the graphs of <paramref name="folder"/> with <paramref name="catalog"/>'s types and runs them with <paramref name="runner"/>.</summary>
    public GraphEditor(GraphFolder folder, PluginCatalog catalog, GraphRunner runner)
    {
        ArgumentNullException.ThrowIfNull(folder);
        ArgumentNullException.ThrowIfNull(catalog);
        ArgumentNullException.ThrowIfNull(runner);
        Folder = folder;
        _catalog = catalog;
        Runner = runner;
        var robot = RobotOf(runner.GraphPath);
        Files = new ConfinedFiles(Folder.Root, robot is null ? null : Path.GetDirectoryName(Path.Combine(Folder.Root, robot)));
    }

    /// <summary>The files the editor may read: the graphs folder and the running graph's robot folder.</summary>
    public ConfinedFiles Files { get; }

    /// <summary>The graphs folder.</summary>
    public GraphFolder Folder { get; }

    /// <summary>Starts and stops the edited graph.</summary>
    public GraphRunner Runner { get; }

    /// <summary>The palette; the robot node is that of <paramref name="robotFile"/> (as a graph names it), else of the running graph's robot.</summary>
    /// <returns>The palette, or null with <paramref name="refusal"/> when the robot file is outside the folders.</returns>
    public CatalogView? Catalog(string? robotFile, out string refusal)
    {
        var robot = robotFile ?? RobotOf(Runner.GraphPath);
        refusal = robot is null ? string.Empty : Files.Problem("robot", robot, Path.Combine(Folder.Root, robot)) ?? string.Empty;
        return refusal.Length > 0 ? null : EditorCatalog.Describe(_catalog, Folder, robot);
    }

    /// <summary>Checks graph text as the loader does; <paramref name="name"/> places it in the folder (null: unsaved).</summary>
    /// <returns>Every problem (none when the graph loads) and each instance's ports, or null with <paramref name="refusal"/> when the name is refused.</returns>
    public CheckView? Check(string? name, string json, out string refusal)
    {
        if (Folder.Resolve(name ?? UntitledName, out refusal) is not null && GraphFileReferences.Problems(json, _catalog, Folder.Root, Files) is { Count: > 0 } refused)
        {
            return new CheckView(refused, new Dictionary<string, PluginPorts>()); // nothing is created that would open those files
        }

        var problems = Load(name, json, out refusal, out var loaded);
        if (problems is null)
        {
            return null;
        }

        if (loaded is not null)
        {
            return new CheckView(problems, EditorCatalog.InstancePorts(loaded, default, _catalog, null, Folder.Root));
        }

        try
        {
            using var document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip });
            var root = document.RootElement;
            var robot = root.ValueKind == JsonValueKind.Object && root.TryGetProperty("robot", out var r) && r.ValueKind == JsonValueKind.String ? TryRobot(r.GetString()!) : null;
            return new CheckView(problems, root.ValueKind == JsonValueKind.Object ? EditorCatalog.InstancePorts(null, root, _catalog, robot, Folder.Root) : new Dictionary<string, PluginPorts>());
        }
        catch (JsonException)
        {
            return new CheckView(problems, new Dictionary<string, PluginPorts>());
        }
    }

    /// <summary>Writes the graph with the loader's writer after checking it; a graph with problems is not written.</summary>
    /// <returns>The problems (empty: written), or null with <paramref name="refusal"/> when the name is refused.</returns>
    public IReadOnlyList<ProblemView>? Save(string name, string json, out string refusal)
    {
        var problems = Load(name, json, out refusal, out var loaded);
        if (loaded is not null)
        {
            GraphFile.Save(loaded.Document, loaded.Path);
        }

        return problems;
    }

    /// <summary>The text of graph file <paramref name="name"/>, or null with <paramref name="refusal"/>.</summary>
    public string? Read(string name, out string refusal)
    {
        var path = Folder.Resolve(name, out refusal);
        if (path is null)
        {
            return null;
        }

        return Files.ReadText("graph", name, path, out refusal);
    }

    private IReadOnlyList<ProblemView>? Load(string? name, string json, out string refusal, out LoadedGraph? loaded)
    {
        loaded = null;
        var path = Folder.Resolve(name ?? UntitledName, out refusal);
        if (path is null)
        {
            return null;
        }

        var refused = GraphFileReferences.Problems(json, _catalog, Folder.Root, Files);
        if (refused.Count > 0)
        {
            return refused;
        }

        try
        {
            loaded = GraphFile.LoadFromText(json, path, _catalog, TimeProvider.System);
            Release(loaded);
            return [];
        }
        catch (GraphException ex)
        {
            return [.. ex.Problems.Select(View)];
        }
    }

    private RobotDefinition? TryRobot(string file)
    {
        if (Files.Problem("robot", file, Path.Combine(Folder.Root, file)) is not null)
        {
            return null;
        }

        try
        {
            return RobotLoader.Load(Path.Combine(Folder.Root, file));
        }
        catch (RobotDataException)
        {
            return null;
        }
    }

    private static ProblemView View(JsonProblem p) => new(p.Path, p.Message);

    /// <summary>Disposes the instances a check created (none of them ever ticked).</summary>
    private static void Release(LoadedGraph loaded)
    {
        foreach (var plugin in loaded.Graph.Instances)
        {
            (plugin as IDisposable)?.Dispose();
        }
    }

    private static string? RobotOf(string? graphPath)
    {
        if (graphPath is null || !File.Exists(graphPath))
        {
            return null;
        }

        try
        {
            using var document = JsonDocument.Parse(File.ReadAllText(graphPath), new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip });
            return document.RootElement.ValueKind == JsonValueKind.Object && document.RootElement.TryGetProperty("robot", out var robot) && robot.ValueKind == JsonValueKind.String
                ? robot.GetString()
                : null;
        }
        catch (JsonException)
        {
            return null;
        }
    }
}
