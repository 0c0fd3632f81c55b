using System.Collections.Concurrent;
using System.Globalization;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Host.Session;
using RobotControl.Kinematics.Urdf;
using RobotControl.Plugins.Sdk.Exchange;

namespace RobotControl.Host.Recording;

/// <summary>
/// Records a session to an MCAP file. The loop thread only copies a row per tick into a ring
/// (<see cref="RecordingTap"/>); this recorder's writer thread drains it, encodes the messages (JSON with JSON Schemas,
/// <see cref="RecordingChannels"/>), reads the supervisor and the bus (<see cref="SessionSources"/>) and does all the
/// I/O. The file starts with metadata (graph, robot, loop rate, start time) and attachments (the graph file, the robot
/// file and its URDF), so it stands alone. A write that fails (a full disk) stops the recording, not the run: the tap
/// is unbound and <see cref="RecordingOptions.Stopped"/> says why, once.
/// </summary>
public sealed class SessionRecorder : IDisposable
{
    /// <summary>The library name written into the file's header.</summary>
    public const string Library = "robotcontrol-mcap";

    /// <summary>The URDF's link frames go on <c>/tf</c> at most this often (loop time): enough for a 3D view, a fraction of the file.</summary>
    private static readonly TimeSpan LinkFramesEvery = TimeSpan.FromMilliseconds(10);

    private readonly RecordingOptions _options;
    private readonly RobotSession _session;
    private readonly RecordingTap _tap;
    private readonly RecordingLayout _layout;
    private readonly SampleRing _ring;
    private readonly Stream _stream;
    private readonly Thread _thread;
    private readonly ulong _startNs;
    private readonly ulong _periodNs;
    private readonly ulong _linksEvery;
    private readonly ConcurrentQueue<(string Who, string What)> _commands = new();
    private volatile bool _stopping;
    private McapWriter? _writer;
    private RecordingSummary? _summary;

    private SessionRecorder(RobotSession session, RecordingTap tap, RecordingOptions options, Stream stream)
    {
        _session = session;
        _tap = tap;
        _options = options;
        _stream = stream;
        _layout = new RecordingLayout(session.Graph);
        _ring = new SampleRing(_layout.Width, options.RingRows);
        _startNs = (ulong)(TimeProvider.System.GetUtcNow() - DateTimeOffset.UnixEpoch).Ticks * 100;
        _periodNs = (ulong)session.Loop.Period.Ticks * 100;
        _linksEvery = (ulong)Math.Max(1, Math.Ceiling(LinkFramesEvery.TotalSeconds / session.Loop.Period.TotalSeconds)) is var every && every % (ulong)options.Decimate == 0 ? every : every * (ulong)options.Decimate;
        _thread = new Thread(WriteUntilStopped) { Name = "recorder (mcap)", IsBackground = true };
    }

    /// <summary>The file.</summary>
    public string Path => _options.Path;

    /// <summary>Why the recording stopped early (one line), or null.</summary>
    public string? StoppedReason { get; private set; }

    /// <summary>
    /// Opens <see cref="RecordingOptions.Path"/> (replacing a file there: the command line asks for <c>--force</c> first),
    /// binds <paramref name="tap"/> and starts the writer thread.
    /// </summary>
    /// <exception cref="IOException">The file cannot be created (one line naming it).</exception>
    public static SessionRecorder Start(RobotSession session, RecordingTap tap, RecordingOptions options)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(tap);
        ArgumentNullException.ThrowIfNull(options);
        ArgumentOutOfRangeException.ThrowIfLessThan(options.Decimate, 1);
        if (options.Compression is not (McapCompression.None or McapCompression.Zstd))
        {
            throw new ArgumentException($"recording compression '{options.Compression}': give '' or 'zstd'", nameof(options));
        }
        Stream stream;
        try
        {
            stream = options.OpenStream?.Invoke(options.Path) ?? new FileStream(options.Path, FileMode.Create, FileAccess.Write, FileShare.Read, 1 << 16);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new IOException($"--record {options.Path}: cannot create the file ({ex.Message})", ex);
        }

        var recorder = new SessionRecorder(session, tap, options, stream);
        tap.Bind(recorder._layout, session.Graph.Program, recorder._ring);
        recorder._thread.Start();
        return recorder;
    }

    /// <summary>
    /// For a run on the virtual clock, which runs as fast as the machine allows: between ticks (never inside one), waits
    /// while the writer has half the ring or more to drain, so that a virtual run loses no row to a writer that is behind
    /// (compiling, at its first recording in the process, or on a loaded machine); virtual time does not move meanwhile.
    /// A real-time run never waits for it: there the ring holds seconds of rows and a full one drops rows, counted.
    /// </summary>
    public void KeepUpWithVirtualTime()
    {
        while (_ring.Count >= _options.RingRows / 2 && StoppedReason is null && _thread.IsAlive)
        {
            Thread.Sleep(1);
        }
    }

    /// <summary>Records an operator command (any thread): who gave it and what it was.</summary>
    public void OperatorCommand(string who, string what)
    {
        _commands.Enqueue((who, what)); // written by the writer thread with its next batch
    }

    /// <summary>Stops recording: unbinds the tap, writes what the ring holds, the summary and the footer; returns what was written.</summary>
    public RecordingSummary Stop()
    {
        if (_summary is null)
        {
            _tap.Unbind();
            _stopping = true;
            _thread.Join();
            var counts = _writer?.CountsByTopic ?? new Dictionary<string, ulong>();
            _summary = new RecordingSummary(Path, counts, _ring.Dropped, _writer?.Position ?? 0, _writer?.ChunkCount ?? 0, StoppedReason);
        }

        return _summary;
    }

    /// <inheritdoc />
    public void Dispose() => Stop();

    private void WriteUntilStopped()
    {
        var now = _startNs;
        try
        {
            _writer = new McapWriter(_stream, string.Empty, Library, compression: _options.Compression);
            WriteHeaderRecords();
            using var channels = new RecordingChannels(_writer, _layout, _session.Robot.Controllers.Select(c => c.Id));
            var sources = new SessionSources(_session.Supervisor, _session.Robot, channels, _startNs, _commands);
            var row = new double[_layout.Width];
            var slowNs = (ulong)_options.SlowEvery.Ticks * 100;
            var lastSlow = 0UL;
            var first = true;
            while (true)
            {
                var any = false;
                while (_ring.TryRead(row))
                {
                    any = true;
                    var loopNs = (ulong)row[0];
                    now = _startNs + loopNs;
                    var tick = (loopNs + (_periodNs / 2)) / _periodNs;
                    channels.WriteRow(row, now, tick % (ulong)_options.Decimate == 0, tick % _linksEvery == 0);
                    if (first || loopNs - lastSlow >= slowNs)
                    {
                        sources.Status(now);
                        lastSlow = loopNs;
                        first = false;
                    }
                }

                sources.Events(now);
                if (_stopping && _ring.Count == 0)
                {
                    break;
                }

                if (!any)
                {
                    Thread.Sleep(2);
                }
            }

            _writer.Finish();
        }
        catch (IOException ex)
        {
            _tap.Unbind();
            StoppedReason = $"recording stopped: {Path}: {ex.Message}; the run goes on";
            _options.Stopped?.Invoke(StoppedReason);
        }
        finally
        {
            try
            {
                _stream.Dispose();
            }
            catch (IOException)
            {
                // the failure was reported above; the file holds what reached it (up to its last complete chunk)
            }
        }
    }

    private void WriteHeaderRecords()
    {
        var graph = _session.Graph;
        var robot = _layout.Robot;
        var c = CultureInfo.InvariantCulture;
        _writer!.AddMetadata("robotcontrol", new Dictionary<string, string>
        {
            ["graph"] = System.IO.Path.GetFileName(graph.Path),
            ["robot"] = robot.Name,
            ["robot_file"] = System.IO.Path.GetFileName(robot.SourceFile),
            ["loop_rate_hz"] = graph.Document.LoopRateHz.ToString(c),
            ["decimate"] = _options.Decimate.ToString(c),
            ["start_unix_ns"] = _startNs.ToString(c),
            ["virtual"] = _session.IsVirtual ? "true" : "false",
            ["arms"] = string.Join(",", robot.Arms.Select(a => a.Name)),
        });
        _writer.AddAttachment(System.IO.Path.GetFileName(graph.Path), "application/json", File.ReadAllBytes(graph.Path), _startNs);
        _writer.AddAttachment(System.IO.Path.GetFileName(robot.SourceFile), "application/json", File.ReadAllBytes(robot.SourceFile), _startNs);
        using var urdf = new StringWriter(c);
        UrdfExport.Write(robot, urdf);
        _writer.AddAttachment(robot.Name + ".urdf", "application/xml", System.Text.Encoding.UTF8.GetBytes(urdf.ToString()), _startNs);
    }
}

/// <summary>What a recording wrote.</summary>
/// <param name="Path">The file.</param>
/// <param name="PerTopic">Messages written, per topic.</param>
/// <param name="DroppedRows">Loop rows dropped because the writer fell behind.</param>
/// <param name="Bytes">Bytes written.</param>
/// <param name="Chunks">Chunks written.</param>
/// <param name="Stopped">Why the recording stopped early, or null.</param>
public sealed record RecordingSummary(string Path, IReadOnlyDictionary<string, ulong> PerTopic, long DroppedRows, long Bytes, int Chunks, string? Stopped)
{
    /// <summary>Messages written (every topic).</summary>
    public ulong Messages => PerTopic.Values.Aggregate(0UL, (a, c) => a + c);

    /// <summary>One line for the command line.</summary>
    public override string ToString() => Stopped ?? string.Create(CultureInfo.InvariantCulture, $"recording: {Path}: {Messages} messages in {Chunks} chunks, {Bytes / 1e6:F1} MB, {DroppedRows} loop rows dropped");
}
