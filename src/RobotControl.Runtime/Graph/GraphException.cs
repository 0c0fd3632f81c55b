using RobotControl.Definitions.Json;

namespace RobotControl.Runtime.Graph;

/// <summary>A graph (or graph file) with problems; <see cref="Problems"/> lists every one. Nothing was applied.</summary>
public sealed class GraphException : Exception
{
    /// <summary>Creates the exception from the problems found.</summary>
    public GraphException(IReadOnlyList<JsonProblem> problems, string? file = null)
        : base(Format(problems, file))
    {
        Problems = problems;
        File = file;
    }

    /// <summary>Creates an exception with one problem.</summary>
    public GraphException(string message)
        : this([new JsonProblem("", message)])
    {
    }

    /// <summary>Creates an exception with one problem and its cause.</summary>
    public GraphException(string message, Exception innerException)
        : base(message, innerException)
    {
        Problems = [new JsonProblem("", message)];
    }

    /// <summary>Creates an empty exception.</summary>
    public GraphException()
        : this("invalid graph")
    {
    }

    /// <summary>Every problem found: a JSON path in the graph file (empty for a graph built in code) and what is wrong.</summary>
    public IReadOnlyList<JsonProblem> Problems { get; }

    /// <summary>The graph file, when loading one.</summary>
    public string? File { get; }

    /// <summary>One problem in one line (<c>file: invalid graph: path: message</c>); more, counted, one per line below.</summary>
    private static string Format(IReadOnlyList<JsonProblem> problems, string? file) =>
        (file is null ? "invalid graph" : $"{file}: invalid graph") + (problems.Count == 1
            ? $": {problems[0]}"
            : $" ({problems.Count} problems):" + string.Concat(problems.Select(p => Environment.NewLine + "  " + p)));
}
