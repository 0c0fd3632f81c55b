using System.Globalization;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Kinematics.Urdf;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Replay;

/// <summary>
/// A recording (<c>--record</c>) read for the console's pages: the graph's signals and each arm's commanded joints as
/// rows of the plots' ring (the live console's names: <c>instance.port</c>, <c>robot.{arm}.{joint}.command</c>), the
/// run levels and trips on the timeline, and the 3D view's model from the recording's URDF attachment.
/// </summary>
internal sealed class ReplayData
{
    private ReplayData(McapContents contents)
    {
        Contents = contents;
        Meta = contents.Metadata.GetValueOrDefault("robotcontrol") ?? [];
    }

    /// <summary>What the file holds.</summary>
    public McapContents Contents { get; }

    /// <summary>The recording's <c>robotcontrol</c> metadata.</summary>
    public IReadOnlyDictionary<string, string> Meta { get; }

    /// <summary>The ring's signal names.</summary>
    public List<string> Names { get; } = [];

    /// <summary>Row times, seconds from the start, ascending.</summary>
    public List<double> Times { get; } = [];

    /// <summary>Rows, one value per name.</summary>
    public List<double[]> Rows { get; } = [];

    /// <summary>Run-level transitions and trips: seconds, source, what.</summary>
    public List<(double Seconds, string Source, string Message)> Timeline { get; } = [];

    /// <summary>The run level after each transition (seconds, level).</summary>
    public List<(double Seconds, string Level)> Levels { get; } = [];

    /// <summary>The 3D view's model.</summary>
    public RobotModelView Model { get; private set; } = new(string.Empty, []);

    /// <summary>Reads <paramref name="path"/>.</summary>
    /// <exception cref="InvalidDataException">Not MCAP, damaged, or not a robotctl recording (one line naming the file).</exception>
    public static ReplayData Load(string path)
    {
        var contents = McapReader.Read(path);
        var data = new ReplayData(contents);
        if (!contents.Channels.Values.Any(c => c.Topic == RecordingTopics.Signals))
        {
            throw new InvalidDataException($"{path}: no {RecordingTopics.Signals} channel: not a robotctl recording (robotctl run --record)");
        }

        data.Build();
        return data;
    }

    private void Build()
    {
        var signals = CsvExport.Tabulate(Contents, RecordingTopics.Signals);
        Names.AddRange(signals.Columns.Skip(1));
        var arms = (Meta.GetValueOrDefault("arms") ?? string.Empty).Split(',', StringSplitOptions.RemoveEmptyEntries);
        var commands = arms.Select(a => (Arm: a, Table: CsvExport.Tabulate(Contents, RecordingTopics.Joints(a)))).ToList();
        var armViews = new List<ArmView>();
        var commandColumns = new List<(int Arm, int Column)>();
        for (var a = 0; a < commands.Count; a++)
        {
            var (arm, table) = commands[a];
            var joints = table.Columns.Where(c => c.StartsWith("setpoint_rad.", StringComparison.Ordinal)).Select(c => c["setpoint_rad.".Length..]).ToList();
            foreach (var joint in joints)
            {
                Names.Add(RingRecorder.CommandSignal(arm, joint));
                commandColumns.Add((a, table.Columns.ToList().IndexOf("setpoint_rad." + joint)));
            }

            armViews.Add(new ArmView(arm, [.. joints.Select(j => UrdfExport.JointName(arm, j))], [.. joints.Select(j => RingRecorder.PositionSignal(arm, j))], [.. joints.Select(j => RingRecorder.CommandSignal(arm, j))]));
        }

        var urdf = Contents.Attachments.FirstOrDefault(p => p.Key.EndsWith(".urdf", StringComparison.Ordinal)).Value ?? string.Empty;
        Model = new RobotModelView(urdf, armViews);
        var jointTimes = commands.Select(c => c.Table.Rows.Select(r => Number(r[0])).ToList()).ToList();
        var cursor = new int[commands.Count];
        foreach (var row in signals.Rows)
        {
            var t = Number(row[0]);
            var values = new double[Names.Count];
            for (var i = 1; i < signals.Columns.Count; i++)
            {
                values[i - 1] = i < row.Length ? Number(row[i]) : double.NaN;
            }

            for (var a = 0; a < commands.Count; a++)
            {
                while (cursor[a] + 1 < jointTimes[a].Count && jointTimes[a][cursor[a] + 1] <= t)
                {
                    cursor[a]++; // the commanded joints recorded at or before this row
                }
            }

            var at = signals.Columns.Count - 1;
            foreach (var (arm, column) in commandColumns)
            {
                var rows = commands[arm].Table.Rows;
                values[at++] = rows.Count == 0 ? double.NaN : Number(rows[cursor[arm]][column]);
            }

            Times.Add(t);
            Rows.Add(values);
        }

        foreach (var row in Table(RecordingTopics.RunLevel))
        {
            Levels.Add((Number(row["time_s"]), Text(row["to"])));
            Timeline.Add((Number(row["time_s"]), Text(row["source"]), $"run level {Text(row["from"])} -> {Text(row["to"])}: {Text(row["reason"])}"));
        }

        foreach (var row in Table(RecordingTopics.Trips))
        {
            Timeline.Add((Number(row["time_s"]), "safety", $"trip: {Text(row["check"])} {Text(row["joint"])} measured {row["measured"]} {Text(row["unit"])} (limit {row["limit"]}), {Text(row["action"])}"));
        }

        Timeline.Sort((x, y) => x.Seconds.CompareTo(y.Seconds));
    }

    private IEnumerable<Dictionary<string, string>> Table(string topic)
    {
        if (!Contents.Channels.Values.Any(c => c.Topic == topic))
        {
            yield break;
        }

        var table = CsvExport.Tabulate(Contents, topic);
        foreach (var row in table.Rows)
        {
            yield return table.Columns.Select((c, i) => (c, i)).ToDictionary(p => p.c, p => p.i < row.Length ? row[p.i] ?? string.Empty : string.Empty);
        }
    }

    private static double Number(string? text) =>
        text is null ? double.NaN : double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out var v) ? v : double.NaN;

    private static string Text(string quoted) => quoted.Length >= 2 && quoted[0] == '"' ? quoted[1..^1].Replace("\"\"", "\"", StringComparison.Ordinal) : quoted;
}
