using RobotControl.Definitions.Json;

namespace RobotControl.Plugins.Sdk.Settings;

/// <summary>Settings that failed validation; <see cref="Errors"/> lists every problem.</summary>
public sealed class SettingsException : Exception
{
    /// <summary>Creates the exception from the problems found.</summary>
    public SettingsException(string instanceName, IReadOnlyList<JsonProblem> errors)
        : base(Format(instanceName, errors))
    {
        Errors = errors;
    }

    /// <summary>Creates an exception with a message only.</summary>
    public SettingsException(string message)
        : base(message)
    {
        Errors = [new JsonProblem("", message)];
    }

    /// <summary>Creates an exception with a message and cause.</summary>
    public SettingsException(string message, Exception innerException)
        : base(message, innerException)
    {
        Errors = [new JsonProblem("", message)];
    }

    /// <summary>Creates an empty exception.</summary>
    public SettingsException()
        : this("invalid settings")
    {
    }

    /// <summary>Every problem found, its path the setting's JSON name (empty for the whole object).</summary>
    public IReadOnlyList<JsonProblem> Errors { get; }

    private static string Format(string instanceName, IReadOnlyList<JsonProblem> errors) =>
        $"'{instanceName}': invalid settings: " + string.Join("; ", errors);
}
