using RobotControl.Definitions.Json;

namespace RobotControl.Definitions.Loading;

/// <summary>Thrown when a data file is invalid; lists every problem found, nothing is half-applied.</summary>
public sealed class RobotDataException : Exception
{
    /// <summary>Creates the exception from the problems found.</summary>
    public RobotDataException(IReadOnlyList<JsonProblem> errors)
        : base(Format(errors))
    {
        Errors = errors;
    }

    /// <summary>Creates an exception with a single message (for tools that wrap a problem).</summary>
    public RobotDataException(string message)
        : base(message)
    {
        Errors = [];
    }

    /// <summary>Creates an exception with a message and an inner exception.</summary>
    public RobotDataException(string message, Exception innerException)
        : base(message, innerException)
    {
        Errors = [];
    }

    /// <summary>Creates an empty exception.</summary>
    public RobotDataException()
    {
        Errors = [];
    }

    /// <summary>Every problem found, each naming its file (<see cref="JsonProblem.File"/>) and JSON path.</summary>
    public IReadOnlyList<JsonProblem> Errors { get; }

    /// <summary>Throws when <paramref name="sink"/> holds any problem.</summary>
    /// <exception cref="RobotDataException">Every problem in the sink.</exception>
    internal static void ThrowIfAny(JsonProblemSink sink)
    {
        if (sink.Problems.Count > 0)
        {
            throw new RobotDataException(sink.Problems.ToArray());
        }
    }

    private static string Format(IReadOnlyList<JsonProblem> errors) =>
        errors.Count == 1
            ? errors[0].ToString()
            : $"{errors.Count} problems:{Environment.NewLine}" + string.Join(Environment.NewLine, errors.Select(e => "  " + e));
}
