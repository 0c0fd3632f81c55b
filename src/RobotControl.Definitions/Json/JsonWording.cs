namespace RobotControl.Definitions.Json;

/// <summary>How a <see cref="JsonFieldReader"/> words the problems it finds; each file format keeps its own.</summary>
public enum JsonWording
{
    /// <summary>
    /// Robot and catalogue files: <c>must be a number, found the string "x"</c>, <c>missing field</c> (naming a field
    /// with the wrong unit suffix), and unknown fields checked against the fields read.
    /// </summary>
    Data,

    /// <summary>
    /// Graph files and plug-in settings: <c>expected a number, found string</c>, <c>is required</c>, and unknown
    /// fields listed with the known ones.
    /// </summary>
    Brief,
}
