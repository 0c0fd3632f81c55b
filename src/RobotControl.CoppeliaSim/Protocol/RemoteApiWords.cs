namespace RobotControl.CoppeliaSim.Protocol;

/// <summary>The reserved words and field names of the ZeroMQ remote API protocol (version 2).</summary>
public static class RemoteApiWords
{
    /// <summary>Protocol version this client speaks (CoppeliaSim 4.6 and later).</summary>
    public const int ProtocolVersion = 2;

    /// <summary>Reply: the server is busy with the call (e.g. <c>sim.step</c>); answer <see cref="Executed"/> until the result comes.</summary>
    public const string Wait = "_*wait*_";

    /// <summary>Request: a callback or wait was handled; its results are the args.</summary>
    public const string Executed = "_*executed*_";

    /// <summary>Reply: the server is busy with another client; send the last request again.</summary>
    public const string Repeat = "_*repeat*_";

    /// <summary>Reply: the server ends the session (e.g. the add-on stops); disconnect.</summary>
    public const string End = "_*end*_";

    /// <summary>How nil travels (Lua drops nil from tables).</summary>
    public const string Nil = "_*NIL*_";

    /// <summary>A newline inside an error message.</summary>
    public const string EscapedNewline = "_=NL=_";

    /// <summary>A tab inside an error message.</summary>
    public const string EscapedTab = "_=TB=_";

    /// <summary>The server's error message with newlines and tabs restored.</summary>
    public static string Unescape(string message)
    {
        ArgumentNullException.ThrowIfNull(message);
        return message.Replace(EscapedNewline, "\n", StringComparison.Ordinal).Replace(EscapedTab, "\t", StringComparison.Ordinal);
    }
}
