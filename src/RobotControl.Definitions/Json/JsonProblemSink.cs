namespace RobotControl.Definitions.Json;

/// <summary>Collects the problems found while reading one JSON document, each tagged with the document's file.</summary>
/// <param name="file">The file the problems are reported against, or null when the document has none.</param>
public sealed class JsonProblemSink(string? file = null)
{
    private readonly List<JsonProblem> _problems = [];

    /// <summary>The file the problems are reported against, or null.</summary>
    public string? File { get; } = file;

    /// <summary>Every problem found so far, in order.</summary>
    public IReadOnlyList<JsonProblem> Problems => _problems;

    /// <summary>Records that the value at <paramref name="path"/> has the problem <paramref name="message"/>.</summary>
    public void Add(string path, string message) => _problems.Add(new JsonProblem(path, message) { File = File });

    /// <summary>True when a problem was recorded at exactly <paramref name="path"/>.</summary>
    public bool HasProblemAt(string path) => _problems.Exists(p => p.Path == path);
}
