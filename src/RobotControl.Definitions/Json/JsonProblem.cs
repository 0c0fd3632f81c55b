namespace RobotControl.Definitions.Json;

/// <summary>
/// One problem found in a JSON document (a robot file, a graph file, a plug-in's settings): where and what.
/// </summary>
/// <param name="Path">
/// The JSON path of the field, e.g. <c>$.dh[2].a_mm</c>; for a problem inside an object read on its own (a plug-in's
/// settings) the path relative to that object, e.g. <c>ratio</c>, or empty for the object itself.
/// </param>
/// <param name="Message">What is wrong.</param>
public sealed record JsonProblem(string Path, string Message)
{
    /// <summary>The file the document came from, when the problem names it.</summary>
    public string? File { get; init; }

    /// <summary>The same problem with its relative path placed under <paramref name="parent"/> (e.g. an instance's settings).</summary>
    public JsonProblem Under(string parent)
    {
        ArgumentNullException.ThrowIfNull(parent);
        return this with { Path = Path.Length == 0 ? parent : $"{parent}.{Path}" };
    }

    /// <summary>The problem in one line: control characters from what the user typed (a key, a value) shown escaped.</summary>
    public override string ToString() => OneLine(
        File is not null ? $"{File}: {Path}: {Message}"
        : Path.Length == 0 ? Message
        : $"{Path}: {Message}");

    /// <summary><paramref name="text"/> with every control character escaped (<c>\n</c>, <c>\t</c>, <c>\u0007</c>), so that it prints as one line.</summary>
    public static string OneLine(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (!text.Any(char.IsControl))
        {
            return text;
        }

        var b = new System.Text.StringBuilder(text.Length + 8);
        foreach (var c in text)
        {
            b.Append(c switch
            {
                '\n' => "\\n",
                '\r' => "\\r",
                '\t' => "\\t",
                _ when char.IsControl(c) => $"\\u{(int)c:X4}",
                _ => c.ToString(),
            });
        }

        return b.ToString();
    }
}
