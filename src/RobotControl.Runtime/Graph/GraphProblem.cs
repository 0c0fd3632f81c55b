namespace RobotControl.Runtime.Graph;

/// <summary>One problem with a graph: where (a JSON path such as <c>$.wires[3].to</c>, or empty) and what.</summary>
/// <param name="Path">Where the problem is (JSON path in the graph file), or empty for a graph built in code.</param>
/// <param name="Message">What is wrong.</param>
public sealed record GraphProblem(string Path, string Message)
{
    /// <inheritdoc />
    public override string ToString() => Path.Length == 0 ? Message : $"{Path}: {Message}";
}

/// <summary>A graph (or graph file) with problems; <see cref="Problems"/> lists every one. Nothing was applied.</summary>
public sealed class GraphException : Exception
{
    /// <summary>Creates the exception from the problems found.</summary>
    public GraphException(IReadOnlyList<GraphProblem> problems, string? file = null)
        : base(Format(problems, file))
    {
        Problems = problems;
        File = file;
    }

    /// <summary>Creates an exception with one problem.</summary>
    public GraphException(string message)
        : this([new GraphProblem("", message)])
    {
    }

    /// <summary>Creates an exception with one problem and its cause.</summary>
    public GraphException(string message, Exception innerException)
        : base(message, innerException)
    {
        Problems = [new GraphProblem("", message)];
    }

    /// <summary>Creates an empty exception.</summary>
    public GraphException()
        : this("invalid graph")
    {
    }

    /// <summary>Every problem found.</summary>
    public IReadOnlyList<GraphProblem> Problems { get; }

    /// <summary>The graph file, when loading one.</summary>
    public string? File { get; }

    private static string Format(IReadOnlyList<GraphProblem> problems, string? file) =>
        (file is null ? "invalid graph" : $"{file}: invalid graph") + $" ({problems.Count} problem{(problems.Count == 1 ? "" : "s")}):"
        + string.Concat(problems.Select(p => Environment.NewLine + "  " + p));
}
