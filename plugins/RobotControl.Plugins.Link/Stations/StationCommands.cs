namespace RobotControl.Plugins.Link.Stations;

/// <summary>The commands a surgeon's station sends to a robot station: a word and an id, e.g. <c>estop 3f2a…</c>.</summary>
public static class StationCommands
{
    /// <summary>The emergency stop: the robot station's supervisor trips <c>operator</c> (E_STOP), from source <c>link</c>.</summary>
    public const string EmergencyStop = "estop";

    /// <summary>A command's text: its word and a new id.</summary>
    public static string New(string word) => $"{word} {Guid.NewGuid():N}";

    /// <summary>Reads a command's word and id; false for anything else.</summary>
    public static bool TryParse(string text, out string word, out string id)
    {
        ArgumentNullException.ThrowIfNull(text);
        var parts = text.Split(' ', StringSplitOptions.RemoveEmptyEntries);
        (word, id) = parts.Length == 2 && parts[0] == EmergencyStop ? (parts[0], parts[1]) : (string.Empty, string.Empty);
        return word.Length > 0;
    }
}
