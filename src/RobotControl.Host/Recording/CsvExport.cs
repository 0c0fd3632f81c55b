using System.Globalization;
using System.Text;
using System.Text.Json;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Host.Recording;

/// <summary>
/// A recording as CSV, for MATLAB and pandas: one table per topic, a <c>time_s</c> column (seconds from the start of
/// the recording) and one column per leaf of the JSON messages, named by its path (<c>position_rad.q1</c>,
/// <c>transforms.0.translation.x</c>); booleans as 1/0, null (a value that was not finite) as NaN.
/// </summary>
public static class CsvExport
{
    /// <summary>The recording's start (ns): its <c>robotcontrol</c> metadata, else its first message.</summary>
    public static ulong StartNs(McapContents contents)
    {
        ArgumentNullException.ThrowIfNull(contents);
        return contents.Metadata.TryGetValue("robotcontrol", out var meta) && meta.TryGetValue("start_unix_ns", out var text) && ulong.TryParse(text, CultureInfo.InvariantCulture, out var start)
            ? start
            : contents.Messages.Count == 0 ? 0 : contents.Messages.Min(m => m.LogTimeNs);
    }

    /// <summary>The file name of <paramref name="topic"/>'s table (<c>/arms/right/joints</c> → <c>arms_right_joints.csv</c>).</summary>
    public static string FileName(string topic) => topic.Trim('/').Replace('/', '_') + ".csv";

    /// <summary>One topic's messages as rows of named values, in file order (time first).</summary>
    public static Table Tabulate(McapContents contents, string topic)
    {
        ArgumentNullException.ThrowIfNull(contents);
        var channel = contents.Channels.Values.FirstOrDefault(c => c.Topic == topic) ?? throw new ArgumentException($"no topic {topic}", nameof(topic));
        var start = StartNs(contents);
        var columns = new List<string> { "time_s" };
        var index = new Dictionary<string, int>(StringComparer.Ordinal) { ["time_s"] = 0 };
        var rows = new List<string[]>();
        foreach (var message in contents.Messages.Where(m => m.ChannelId == channel.Id))
        {
            var values = new Dictionary<int, string> { [0] = ((long)(message.LogTimeNs - start) / 1e9).ToString("R", CultureInfo.InvariantCulture) };
            using var doc = JsonDocument.Parse(message.Data);
            Flatten(doc.RootElement, string.Empty, (name, value) =>
            {
                if (!index.TryGetValue(name, out var i))
                {
                    index[name] = i = columns.Count;
                    columns.Add(name);
                }

                values[i] = value;
            });
            var row = new string[columns.Count];
            foreach (var (i, value) in values)
            {
                row[i] = value;
            }

            rows.Add(row);
        }

        return new Table(columns, rows);
    }

    /// <summary>Writes <paramref name="topics"/> (null: every topic) of <paramref name="contents"/> into <paramref name="directory"/>; returns the files written.</summary>
    /// <exception cref="ArgumentException">A topic the file does not have (the message lists those it has).</exception>
    public static IReadOnlyList<string> Write(McapContents contents, string directory, IReadOnlyList<string>? topics = null)
    {
        ArgumentNullException.ThrowIfNull(contents);
        var known = contents.Channels.Values.Select(c => c.Topic).ToList();
        var unknown = topics?.Where(t => !known.Contains(t)).ToList() ?? [];
        if (unknown.Count > 0)
        {
            throw new ArgumentException($"--topics: {Path.GetFileName(contents.Path)} has no topic {string.Join(", ", unknown)} (it has {string.Join(", ", known)})");
        }

        Directory.CreateDirectory(directory);
        var written = new List<string>();
        foreach (var topic in topics ?? known)
        {
            var table = Tabulate(contents, topic);
            var path = Path.Combine(directory, FileName(topic));
            var text = new StringBuilder();
            text.AppendLine(string.Join(',', table.Columns));
            foreach (var row in table.Rows)
            {
                for (var i = 0; i < table.Columns.Count; i++)
                {
                    if (i > 0)
                    {
                        text.Append(',');
                    }

                    text.Append(i < row.Length ? row[i] : string.Empty);
                }

                text.AppendLine();
            }

            var temporary = path + ".tmp";
            File.WriteAllText(temporary, text.ToString());
            File.Move(temporary, path, overwrite: true);
            written.Add(path);
        }

        return written;
    }

    private static void Flatten(JsonElement e, string prefix, Action<string, string> add)
    {
        switch (e.ValueKind)
        {
            case JsonValueKind.Object:
                foreach (var p in e.EnumerateObject())
                {
                    Flatten(p.Value, prefix.Length == 0 ? p.Name : $"{prefix}.{p.Name}", add);
                }

                break;
            case JsonValueKind.Array:
                var i = 0;
                foreach (var item in e.EnumerateArray())
                {
                    Flatten(item, $"{prefix}.{i++}", add);
                }

                break;
            case JsonValueKind.Number:
                add(prefix, e.GetRawText());
                break;
            case JsonValueKind.True:
                add(prefix, "1");
                break;
            case JsonValueKind.False:
                add(prefix, "0");
                break;
            case JsonValueKind.Null:
                add(prefix, "NaN");
                break;
            default:
                add(prefix, Quote(e.GetString() ?? string.Empty));
                break;
        }
    }

    private static string Quote(string text) => "\"" + text.Replace("\"", "\"\"", StringComparison.Ordinal) + "\"";

    /// <summary>A topic as a table.</summary>
    /// <param name="Columns">Column names, <c>time_s</c> first.</param>
    /// <param name="Rows">One row per message (a cell missing in a message is null).</param>
    public sealed record Table(IReadOnlyList<string> Columns, IReadOnlyList<string?[]> Rows);
}
