using System.Globalization;
using System.Text;
using System.Text.Json;
using RobotControl.Host.Recording.Mcap;

namespace RobotControl.Host.Recording;

/// <summary>
/// A recording as CSV, for MATLAB and pandas: one table per topic, a <c>time_s</c> column (seconds from the start of
/// the recording) and one column per leaf of the JSON messages (in the order they first appear), named by its path (<c>position_rad.q1</c>,
/// <c>transforms.0.translation.x</c>); booleans as 1/0, null (a value that was not finite) as NaN.
/// </summary>
public static class CsvExport
{
    /// <summary>The recording's start (ns): its <c>robotcontrol</c> metadata, else its first message.</summary>
    public static ulong StartNs(McapFile file)
    {
        ArgumentNullException.ThrowIfNull(file);
        return file.Metadata.TryGetValue("robotcontrol", out var meta) && meta.TryGetValue("start_unix_ns", out var text) && ulong.TryParse(text, CultureInfo.InvariantCulture, out var start)
            ? start
            : file.StartNs;
    }

    /// <summary>The file name of <paramref name="topic"/>'s table (<c>/arms/right/joints</c> → <c>arms_right_joints.csv</c>).</summary>
    public static string FileName(string topic) => topic.Trim('/').Replace('/', '_') + ".csv";

    /// <summary>One topic's messages as rows of named values, in log-time order (time first), held in memory: for a test or a short file.</summary>
    /// <exception cref="ArgumentException">No such topic.</exception>
    public static Table Tabulate(McapFile file, string topic)
    {
        ArgumentNullException.ThrowIfNull(file);
        var channel = file.Channel(topic) ?? throw new ArgumentException($"no topic {topic}", nameof(topic));
        var columns = new Columns();
        var rows = new List<string?[]>();
        var start = StartNs(file);
        foreach (var message in file.Messages([channel.Id]))
        {
            rows.Add(columns.Row(message, start));
        }

        return new Table(columns.Names, rows);
    }

    /// <summary>
    /// Writes <paramref name="topics"/> (null: every topic) of <paramref name="file"/> into <paramref name="directory"/>
    /// in one pass through the file, a chunk at a time, so a file of any size is exported in bounded memory; each CSV is
    /// written beside its final name and moved there when whole. Returns the files written and the rows in them.
    /// </summary>
    /// <exception cref="ArgumentException">A topic the file does not have (the message lists those it has).</exception>
    public static (IReadOnlyList<string> Files, long Rows) Write(McapFile file, string directory, IReadOnlyList<string>? topics = null)
    {
        ArgumentNullException.ThrowIfNull(file);
        var known = file.Channels.Values.OrderBy(c => c.Id).Select(c => c.Topic).ToList();
        var unknown = topics?.Where(t => !known.Contains(t)).ToList() ?? [];
        if (unknown.Count > 0)
        {
            throw new ArgumentException($"--topics: {Path.GetFileName(file.Path)} has no topic {string.Join(", ", unknown)} (it has {string.Join(", ", known)})");
        }

        Directory.CreateDirectory(directory);
        var start = StartNs(file);
        var tables = (topics ?? known).Distinct().ToDictionary(t => file.Channel(t)!.Id, t => new TopicCsv(Path.Combine(directory, FileName(t))));
        long rows = 0;
        try
        {
            foreach (var message in file.Messages(tables.Keys))
            {
                tables[message.ChannelId].Add(message, start);
                rows++;
            }

            return ([.. tables.Values.Select(t => t.Finish())], rows);
        }
        finally
        {
            foreach (var table in tables.Values)
            {
                table.Dispose();
            }
        }
    }

    /// <summary>The column names of <paramref name="json"/>'s leaves, in order, as a table of its topic names them (<c>instance.port</c>): the names the replay gives the plots.</summary>
    public static List<string> LeafNames(ReadOnlyMemory<byte> json)
    {
        using var doc = JsonDocument.Parse(json);
        var names = new List<string>();
        Flatten(doc.RootElement, string.Empty, (name, _) => names.Add(name));
        return names;
    }

    /// <summary>The columns of one topic's table, in the order their leaves first appear.</summary>
    private sealed class Columns
    {
        private readonly Dictionary<string, int> _index = new(StringComparer.Ordinal) { ["time_s"] = 0 };

        public List<string> Names { get; } = ["time_s"];

        /// <summary>The cells of <paramref name="message"/> (time first), by column; a column it lacks is null.</summary>
        public string?[] Row(McapMessage message, ulong startNs)
        {
            var values = new List<(int Column, string Value)> { (0, ((long)(message.LogTimeNs - startNs) / 1e9).ToString("R", CultureInfo.InvariantCulture)) };
            using var doc = JsonDocument.Parse(message.Data);
            Flatten(doc.RootElement, string.Empty, (name, value) =>
            {
                if (!_index.TryGetValue(name, out var i))
                {
                    _index[name] = i = Names.Count;
                    Names.Add(name);
                }

                values.Add((i, value));
            });
            var row = new string?[Names.Count];
            foreach (var (i, value) in values)
            {
                row[i] = value;
            }

            return row;
        }
    }

    /// <summary>One topic's CSV being written: rows to a body file as they come, the header (every column seen) in front at the end.</summary>
    private sealed class TopicCsv(string path) : IDisposable
    {
        private readonly Columns _columns = new();
        private readonly string _body = path + ".rows.tmp";
        private StreamWriter? _writer;

        public void Add(McapMessage message, ulong startNs)
        {
            _writer ??= new StreamWriter(_body, append: false, new UTF8Encoding(false), 1 << 16);
            var row = _columns.Row(message, startNs);
            for (var i = 0; i < row.Length; i++)
            {
                if (i > 0)
                {
                    _writer.Write(',');
                }

                _writer.Write(row[i]);
            }

            _writer.Write('\n');
        }

        public string Finish()
        {
            var temporary = path + ".tmp";
            using (var output = new FileStream(temporary, FileMode.Create, FileAccess.Write))
            {
                output.Write(Encoding.UTF8.GetBytes(string.Join(',', _columns.Names) + "\n"));
                if (_writer is not null)
                {
                    _writer.Dispose();
                    _writer = null;
                    using var body = File.OpenRead(_body);
                    body.CopyTo(output);
                }
            }

            File.Move(temporary, path, overwrite: true);
            File.Delete(_body);
            return path;
        }

        public void Dispose()
        {
            _writer?.Dispose();
            File.Delete(_body);
            File.Delete(path + ".tmp");
        }
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
