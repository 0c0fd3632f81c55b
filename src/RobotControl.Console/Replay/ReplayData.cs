using System.Globalization;
using System.Text.Json;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Kinematics.Urdf;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Replay;

/// <summary>
/// What the replay learns when it opens a recording (<c>--record</c>), by the file's index: the plots' signal names (the
/// live console's: <c>instance.port</c> for the graph's signals, <c>robot.{arm}.{joint}.command</c> for each arm's
/// commanded joints), the run levels, trips and operator commands on the timeline, and the 3D view's model from the
/// recording's URDF attachment. The rows themselves stay in the file and are read as the playback reaches them
/// (<see cref="ReplayRows"/>).
/// </summary>
internal sealed class ReplayData : IDisposable
{
    private ReplayData(McapFile file, McapChannel signals)
    {
        File = file;
        Meta = file.Metadata.GetValueOrDefault("robotcontrol") ?? new Dictionary<string, string>();
        StartNs = CsvExport.StartNs(file);
        Signals = signals.Id;
    }

    /// <summary>The recording.</summary>
    public McapFile File { get; }

    /// <summary>The recording's <c>robotcontrol</c> metadata.</summary>
    public IReadOnlyDictionary<string, string> Meta { get; }

    /// <summary>Log time of the recording's start (ns): times are seconds from it.</summary>
    public ulong StartNs { get; }

    /// <summary>The graph's signals channel.</summary>
    public ushort Signals { get; }

    /// <summary>Each arm's joints channel.</summary>
    public List<ushort> Joints { get; } = [];

    /// <summary>How many leading values of a row are the graph's signals (the arms' commanded joints follow).</summary>
    public int SignalCount { get; private set; }

    /// <summary>Each arm's joint count, in the order of <see cref="Joints"/>.</summary>
    public List<int> JointCounts { get; } = [];

    /// <summary>The ring's signal names.</summary>
    public List<string> Names { get; } = [];

    /// <summary>The recorded loop's rate (Hz, its metadata), or 0 when the metadata does not say.</summary>
    public double LoopRateHz =>
        double.TryParse(Meta.GetValueOrDefault("loop_rate_hz"), NumberStyles.Float, CultureInfo.InvariantCulture, out var hz) && hz > 0 ? hz : 0;

    /// <summary>Time between two recorded rows of the graph's signals (decimation over loop rate), seconds; 1 when the metadata does not say.</summary>
    public double RowSpacingSeconds =>
        LoopRateHz > 0
            ? (int.TryParse(Meta.GetValueOrDefault("decimate"), NumberStyles.Integer, CultureInfo.InvariantCulture, out var n) && n > 0 ? n : 1) / LoopRateHz
            : 1;

    /// <summary>Length of the recording, seconds.</summary>
    public double DurationSeconds => File.EndNs <= StartNs ? 0 : Seconds(File.EndNs);

    /// <summary>Run-level transitions, trips and operator commands: seconds, source, what.</summary>
    public List<(double Seconds, string Source, string Message)> Timeline { get; } = [];

    /// <summary>The run level after each transition (seconds, level).</summary>
    public List<(double Seconds, string Level)> Levels { get; } = [];

    /// <summary>The 3D view's model.</summary>
    public RobotModelView Model { get; private set; } = new(string.Empty, []);

    /// <summary>Opens <paramref name="path"/>.</summary>
    /// <exception cref="InvalidDataException">Not MCAP, damaged, or not a robotctl recording (one line naming the file).</exception>
    public static ReplayData Load(string path)
    {
        var file = McapFile.Open(path);
        try
        {
            var signals = file.Channel(RecordingTopics.Signals) ?? throw new InvalidDataException($"{path}: no {RecordingTopics.Signals} channel: not a robotctl recording (robotctl run --record)");
            var data = new ReplayData(file, signals);
            data.Build();
            return data;
        }
        catch
        {
            file.Dispose();
            throw;
        }
    }

    /// <summary>Seconds from the start of log time <paramref name="ns"/>.</summary>
    public double Seconds(ulong ns) => (long)(ns - StartNs) / 1e9;

    /// <summary>Log time (ns) of <paramref name="seconds"/> from the start.</summary>
    public ulong Ns(double seconds) => StartNs + (ulong)Math.Max(0, Math.Round(seconds * 1e9));

    /// <inheritdoc />
    public void Dispose() => File.Dispose();

    private void Build()
    {
        if (File.Messages([Signals]).FirstOrDefault() is { } first)
        {
            Names.AddRange(CsvExport.LeafNames(first.Data));
        }

        SignalCount = Names.Count;
        var arms = (Meta.GetValueOrDefault("arms") ?? string.Empty).Split(',', StringSplitOptions.RemoveEmptyEntries);
        var armViews = new List<ArmView>();
        foreach (var arm in arms)
        {
            if (File.Channel(RecordingTopics.Joints(arm)) is not { } channel)
            {
                continue;
            }

            var joints = new List<string>();
            if (File.Messages([channel.Id]).FirstOrDefault() is { } message)
            {
                using var doc = JsonDocument.Parse(message.Data);
                joints.AddRange(doc.RootElement.GetProperty("setpoint_rad").EnumerateObject().Select(p => p.Name));
            }

            Joints.Add(channel.Id);
            JointCounts.Add(joints.Count);
            Names.AddRange(joints.Select(j => RingRecorder.CommandSignal(arm, j)));
            armViews.Add(new ArmView(arm, [.. joints.Select(j => UrdfExport.JointName(arm, j))], [.. joints.Select(j => RingRecorder.PositionSignal(arm, j))], [.. joints.Select(j => RingRecorder.CommandSignal(arm, j))]));
        }

        var urdf = File.Attachments.FirstOrDefault(p => p.Key.EndsWith(".urdf", StringComparison.Ordinal)).Value ?? string.Empty;
        Model = new RobotModelView(urdf, armViews);
        BuildTimeline();
    }

    private void BuildTimeline()
    {
        var levels = File.Channel(RecordingTopics.RunLevel)?.Id;
        var trips = File.Channel(RecordingTopics.Trips)?.Id;
        var commands = File.Channel(RecordingTopics.Operator)?.Id;
        var wanted = new[] { levels, trips, commands }.OfType<ushort>().ToList();
        foreach (var message in wanted.Count == 0 ? [] : File.Messages(wanted))
        {
            var t = Seconds(message.LogTimeNs);
            using var doc = JsonDocument.Parse(message.Data);
            var e = doc.RootElement;
            if (message.ChannelId == levels)
            {
                Levels.Add((t, Text(e, "to")));
                Timeline.Add((t, Text(e, "source"), $"run level {Text(e, "from")} -> {Text(e, "to")}: {Text(e, "reason")}"));
            }
            else if (message.ChannelId == trips)
            {
                Timeline.Add((t, "safety", $"trip: {Text(e, "check")} {Text(e, "joint")} measured {Text(e, "measured")} {Text(e, "unit")} (limit {Text(e, "limit")}), {Text(e, "action")}"));
            }
            else
            {
                Timeline.Add((t, Text(e, "who"), Text(e, "what")));
            }
        }
    }

    private static string Text(JsonElement e, string name) => !e.TryGetProperty(name, out var v) ? "?" : v.ValueKind switch
    {
        JsonValueKind.String => v.GetString()!,
        JsonValueKind.Number => v.GetDouble().ToString("R", CultureInfo.InvariantCulture),
        JsonValueKind.Null => "NaN",
        _ => v.GetRawText(),
    };
}
