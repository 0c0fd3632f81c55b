using System.Globalization;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Replay;

/// <summary>
/// The console's pages served from a recording (<c>robotctl console --replay file.mcap</c>): no robot. A playback
/// clock (on an injected <see cref="TimeProvider"/>) moves through the recording at 0.25x to 4x; <see cref="Pump"/>
/// appends the rows recorded up to the playback position to the plots' ring (read from the file as the playback reaches
/// them, <see cref="ReplayRows"/>), so the plots and the 3D view show them as they showed the live session; the status
/// page shows the run level at that time and the trips so far, and the event log the run-level transitions, trips and
/// operator commands up to it. A chunk found damaged on the way pauses the playback there and says so. Every robot
/// command is refused.
/// </summary>
public sealed class ReplaySession : RobotlessSession
{
    /// <summary>Slowest and fastest playback.</summary>
    public const double MinRate = 0.25, MaxRate = 4;

    private readonly ReplayData _data;
    private readonly ReplayRows _rows;
    private readonly TimeProvider _time;
    private readonly string _file;
    private readonly Lock _gate = new();
    private readonly ITimer? _timer;
    private long _lastWall;
    private double _position;
    private double _rate = 1;
    private bool _playing = true;
    private volatile SessionStatus _status;

    /// <summary>Opens <paramref name="path"/>; with <paramref name="pumpEvery"/>, a timer pumps the ring at that interval.</summary>
    /// <exception cref="InvalidDataException">Not a recording robotctl can replay (one line naming the file).</exception>
    public ReplaySession(string path, TimeProvider time, TimeSpan? pumpEvery = null)
        : base("a replay: no robot to command")
    {
        ArgumentNullException.ThrowIfNull(path);
        ArgumentNullException.ThrowIfNull(time);
        _data = ReplayData.Load(path);
        _rows = new ReplayRows(_data);
        _time = time;
        _file = Path.GetFileName(path);
        Signals = new SignalRing(_data.Names, [.. _data.Names.Select(_ => string.Empty)], 16384);
        Model = _data.Model;
        Truncated = _data.File.Truncated;
        _lastWall = time.GetTimestamp();
        _status = BuildStatus();
        _timer = pumpEvery is { } every ? time.CreateTimer(_ => Pump(), null, every, every) : null;
    }

    /// <summary>Where and why the file was cut short (played up to its last complete chunk), or null.</summary>
    public string? Truncated { get; }

    /// <summary>Length of the recording, seconds.</summary>
    public double DurationSeconds => _data.DurationSeconds;

    /// <summary>Where the file was found damaged during the playback (which paused there), or null.</summary>
    public string? Damaged { get; private set; }

    /// <summary>The playback position, seconds from the start.</summary>
    public double PositionSeconds
    {
        get
        {
            lock (_gate)
            {
                return _position;
            }
        }
    }

    /// <inheritdoc />
    public override SessionStatus Status => _status;

    /// <inheritdoc />
    public override SignalRing Signals { get; }

    /// <inheritdoc />
    public override RobotModelView Model { get; }

    /// <inheritdoc />
    public override SurgeonView Surgeon { get; } = new([], [], []);

    /// <inheritdoc />
    public override WorkspaceView Workspace { get; } = new([]);

    /// <summary>Plays or pauses.</summary>
    public void Play(bool playing) => Control(() => _playing = playing);

    /// <summary>Sets the playback rate.</summary>
    /// <exception cref="ArgumentOutOfRangeException">Outside <see cref="MinRate"/>..<see cref="MaxRate"/>.</exception>
    public void Rate(double rate)
    {
        if (!(rate >= MinRate && rate <= MaxRate))
        {
            throw new ArgumentOutOfRangeException(nameof(rate), rate, string.Create(CultureInfo.InvariantCulture, $"replay rate {rate}: give {MinRate} to {MaxRate}"));
        }

        Control(() => _rate = rate);
    }

    /// <summary>Moves the playback position to <paramref name="seconds"/> (clamped to the recording); the ring continues from there.</summary>
    public void Seek(double seconds) => Control(() =>
    {
        _position = Math.Clamp(double.IsFinite(seconds) ? seconds : 0, 0, DurationSeconds);
        Read(() => _rows.Seek(_position)); // the row shown at the new position comes first
    });

    /// <summary>Moves the playback clock to now and appends the rows up to the position to the ring (the timer's work; tests call it).</summary>
    public void Pump()
    {
        lock (_gate)
        {
            Advance();
            Read(() =>
            {
                while (_rows.TryNext(_position, out var time, out var row))
                {
                    Signals.Append(time, row);
                }
            });
            _status = BuildStatus();
        }
    }

    /// <summary>The whole recording's run-level transitions and trips (the timeline), whatever the position.</summary>
    public IReadOnlyList<EventEntry> Timeline => [.. _data.Timeline.Select((e, i) => new EventEntry(i + 1, e.Seconds, e.Source, e.Message))];

    /// <inheritdoc />
    public override IReadOnlyList<EventEntry> EventsAfter(long after)
    {
        var position = PositionSeconds;
        return [.. Timeline.Where(e => e.Sequence > after && e.TimeSeconds <= position)];
    }

    /// <summary>Accepted, as everywhere: a replay has no motors to stop.</summary>
    public override Task<CommandResult> EmergencyStopAsync() => Task.FromResult(CommandResult.Ok("a replay: no motors run"));

    /// <inheritdoc />
    public override SessionEnd Close()
    {
        _timer?.Dispose();
        return new SessionEnd(_status with { Session = "stopped" }, null, EventsAfter(0), []);
    }

    /// <inheritdoc />
    protected override void Dispose(bool disposing)
    {
        _timer?.Dispose();
        lock (_gate)
        {
            _rows.Dispose();
            _data.Dispose();
        }

        base.Dispose(disposing);
    }

    /// <summary>Runs a read of the file; a damaged chunk pauses the playback where it is and is said once.</summary>
    private void Read(Action read)
    {
        if (Damaged is not null)
        {
            return;
        }

        try
        {
            read();
        }
        catch (InvalidDataException ex)
        {
            Damaged = $"{ex.Message}; the replay paused at {_position.ToString("F3", CultureInfo.InvariantCulture)} s";
            _playing = false;
        }
    }

    private void Control(Action change)
    {
        lock (_gate)
        {
            Advance();
            change();
            _status = BuildStatus();
        }
    }

    private void Advance()
    {
        var now = _time.GetTimestamp();
        if (_playing)
        {
            _position = Math.Min(DurationSeconds, _position + (_time.GetElapsedTime(_lastWall, now).TotalSeconds * _rate));
        }

        _lastWall = now;
    }

    private SessionStatus BuildStatus()
    {
        var level = _data.Levels.LastOrDefault(l => l.Seconds <= _position).Level ?? "INIT";
        var trips = _data.Timeline.Where(e => e.Seconds <= _position && e.Message.StartsWith("trip: ", StringComparison.Ordinal)).Select(e => e.Message).ToList();
        var state = Damaged ?? string.Create(CultureInfo.InvariantCulture, $"replay {(_playing ? "playing" : "paused")} at {_rate:0.##}x, {_position:F3} of {DurationSeconds:F3} s");
        return new SessionStatus(
            _data.Meta.GetValueOrDefault("robot") ?? "?",
            _data.Meta.GetValueOrDefault("graph") ?? "?",
            "replay:" + _file,
            0,
            0,
            _data.LoopRateHz,
            _rows.Count,
            0,
            0,
            0,
            0,
            null,
            _position,
            level,
            "replay",
            state,
            false,
            trips,
            0,
            new BusCounters(0, 0, 0, 0, 0));
    }
}
