namespace RobotControl.Plugins.Link;

/// <summary>The signal names a link carries (its ports), parsed from the <c>signals</c> setting.</summary>
internal static class LinkSignals
{
    /// <summary>Most signals one link carries.</summary>
    public const int Capacity = SampleValues.Capacity;

    /// <summary>The names, in order (the settings were checked).</summary>
    public static string[] Parse(string text) => text.Split(',', StringSplitOptions.TrimEntries);

    /// <summary>A problem with the list, or null.</summary>
    public static string? Check(string text)
    {
        if (string.IsNullOrWhiteSpace(text))
        {
            return null; // the Required check names it
        }

        var names = Parse(text);
        if (names.Length > Capacity)
        {
            return $"{names.Length} signals; a link carries at most {Capacity}";
        }

        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var name in names)
        {
            if (name.Length == 0 || name.Any(c => !(char.IsAsciiLetterOrDigit(c) || c is '_' or '.')))
            {
                return $"'{name}' is not a signal name (letters, digits, _ and .)";
            }

            if (name is LinkInPlugin.AgePort or LinkInPlugin.ConnectedPort or LinkInPlugin.FreshPort or LinkInPlugin.SequencePort
                or LinkInPlugin.GapsPort or LinkInPlugin.ReorderedPort or LinkInPlugin.BadFramesPort or LinkOutPlugin.DroppedPort)
            {
                return $"'{name}' is the name of one of the link's own ports";
            }

            if (!seen.Add(name))
            {
                return $"'{name}' is listed twice";
            }
        }

        return null;
    }

    /// <summary>The names of <paramref name="subset"/> (empty: none), each one of the link's signals; the settings were checked.</summary>
    public static string[] ParseSubset(string subset) => string.IsNullOrWhiteSpace(subset) ? [] : Parse(subset);

    /// <summary>A problem with <paramref name="subset"/>, a list of some of <paramref name="signals"/>, or null.</summary>
    public static string? CheckSubset(string subset, string signals)
    {
        var all = Parse(signals);
        var seen = new HashSet<string>(StringComparer.Ordinal);
        foreach (var name in ParseSubset(subset))
        {
            if (!all.Contains(name, StringComparer.Ordinal))
            {
                return $"'{name}' is not one of the link's signals ({string.Join(", ", all)})";
            }

            if (!seen.Add(name))
            {
                return $"'{name}' is listed twice";
            }
        }

        return null;
    }
}
