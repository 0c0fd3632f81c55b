namespace RobotControl.Hardware.Loading;

/// <summary>One problem found in a data file: which file, which field (JSON path) and what is wrong.</summary>
/// <param name="File">The file's path.</param>
/// <param name="JsonPath">JSON path of the field, e.g. <c>$.dh[2].a_mm</c>.</param>
/// <param name="Message">What is wrong.</param>
public sealed record DataError(string File, string JsonPath, string Message)
{
    /// <inheritdoc />
    public override string ToString() => $"{File}: {JsonPath}: {Message}";
}

/// <summary>Thrown when a data file is invalid; lists every problem found, nothing is half-applied.</summary>
public sealed class RobotDataException : Exception
{
    /// <summary>Creates the exception from the problems found.</summary>
    public RobotDataException(IReadOnlyList<DataError> errors)
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

    /// <summary>Every problem found.</summary>
    public IReadOnlyList<DataError> Errors { get; }

    private static string Format(IReadOnlyList<DataError> errors) =>
        errors.Count == 1
            ? errors[0].ToString()
            : $"{errors.Count} problems:{Environment.NewLine}" + string.Join(Environment.NewLine, errors.Select(e => "  " + e));
}
