using RobotControl.Definitions.Json;

namespace RobotControl.Runtime.GraphFiles;

/// <summary>One <c>--set &lt;instance&gt;.&lt;setting&gt;=&lt;value&gt;</c>: a setting of a graph instance replaced for one run.</summary>
/// <param name="Instance">Instance name.</param>
/// <param name="Setting">Setting name as graph files write it (snake_case).</param>
/// <param name="Value">The value as typed; numbers, integers and booleans are read as such for settings of that kind.</param>
public sealed record SettingOverride(string Instance, string Setting, string Value)
{
    /// <summary>Reads <c>instance.setting=value</c> (the value may contain '=' and '.').</summary>
    /// <exception cref="FormatException">Not of that form; the message names the option and the text.</exception>
    public static SettingOverride Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var equals = text.IndexOf('=', StringComparison.Ordinal);
        var name = equals > 0 ? text[..equals].Trim() : "";
        var dot = name.IndexOf('.', StringComparison.Ordinal);
        if (dot <= 0 || dot == name.Length - 1)
        {
            throw new FormatException($"--set '{JsonProblem.OneLine(text)}': expected <instance>.<setting>=<value>, e.g. sim.endpoint=tcp://127.0.0.1:23456");
        }

        return new SettingOverride(name[..dot], name[(dot + 1)..], text[(equals + 1)..]);
    }

    /// <summary>As typed, in one line (control characters escaped, <see cref="JsonProblem.OneLine"/>).</summary>
    public override string ToString() => JsonProblem.OneLine($"{Instance}.{Setting}={Value}");
}
