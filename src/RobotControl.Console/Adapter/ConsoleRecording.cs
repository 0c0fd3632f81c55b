using RobotControl.Host.Recording;
using RobotControl.Host.Session;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console session's MCAP recording (docs/recording.md): started with the session (<c>--record</c>) or by the
/// record button (a new file in the recordings folder, named by the time), stopped by the button or at the session's
/// stop, after the motors are off. One recording at a time, on the loop's <see cref="RecordingTap"/>; what each start
/// and stop did goes to the event log.
/// </summary>
internal sealed class ConsoleRecording(RobotSession session, RecordingTap tap, SessionEvents events, RecordingOptions? first, string? folder)
{
    private readonly Lock _gate = new();
    private readonly string _folder = folder ?? (first is null ? Path.Combine(Directory.GetCurrentDirectory(), "recordings") : Path.GetDirectoryName(first.Path)!);
    private SessionRecorder? _recorder;

    /// <summary>The file being recorded, or null.</summary>
    public string? File => _recorder?.Path;

    /// <summary>Starts the recording asked for at the session's start (<c>--record</c>), if any.</summary>
    /// <exception cref="IOException">The file cannot be created (one line naming it).</exception>
    public void StartFirst()
    {
        if (first is not null)
        {
            _recorder = SessionRecorder.Start(session, tap, first with { Stopped = Stopped(first.Stopped) });
            events.Add("session", $"recording to {first.Path}");
        }
    }

    /// <summary>The record button: starts a new file or stops the recording.</summary>
    public CommandResult Record(bool on)
    {
        lock (_gate)
        {
            if (!on)
            {
                return _recorder is null ? CommandResult.Fail(CommandOutcome.Refused, "not recording") : CommandResult.Ok(StopLocked()!);
            }

            if (_recorder is not null)
            {
                return CommandResult.Fail(CommandOutcome.Refused, $"already recording to {_recorder.Path}");
            }

            try
            {
                Directory.CreateDirectory(_folder);
                var path = Path.Combine(_folder, $"session-{DateTime.UtcNow:yyyyMMdd-HHmmss-fff}.mcap");
                _recorder = SessionRecorder.Start(session, tap, (first ?? new RecordingOptions { Path = path }) with { Path = path, Stopped = Stopped(null) });
                events.Add("session", $"recording to {path}");
                return CommandResult.Ok($"recording to {path}");
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
            {
                return CommandResult.Fail(CommandOutcome.Refused, $"recording not started: {ex.Message}");
            }
        }
    }

    /// <summary>Notes an operator command in the recording, if one runs (any thread: the recorder queues it for its writer).</summary>
    public void Note(string who, string what) => Volatile.Read(ref _recorder)?.OperatorCommand(who, what);

    /// <summary>Stops the recording (the session's stop, after the motors are off); says what was written, or null.</summary>
    public string? Stop()
    {
        lock (_gate)
        {
            return StopLocked();
        }
    }

    private string? StopLocked()
    {
        if (_recorder is not { } recorder)
        {
            return null;
        }

        _recorder = null;
        var line = recorder.Stop().ToString();
        events.Add("session", line);
        return line;
    }

    private Action<string> Stopped(Action<string>? also) => line =>
    {
        events.Add("session", line);
        also?.Invoke(line);
    };
}
