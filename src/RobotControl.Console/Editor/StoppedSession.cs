using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// What the pages see after the graph editor stopped the graph: the last status with the session <c>stopped</c>, no
/// controllers and no signals; every command is refused until a graph starts again.
/// </summary>
internal sealed class StoppedSession : IConsoleSession
{
    private const string Refusal = "no graph runs: start one from the graph editor";
    private volatile IReadOnlyList<EventEntry> _events;
    private volatile SessionEnd? _end;

    /// <summary>What is left of <paramref name="last"/>: its status (stopped), robot model, workspace, events and faults.</summary>
    public StoppedSession(IConsoleSession last)
    {
        ArgumentNullException.ThrowIfNull(last);
        Status = last.Status with { Session = "stopped", TorqueOn = false, RobotState = "INIT", RobotLayer = "Disabled", ModulesFound = 0 };
        Model = last.Model;
        Workspace = last.Workspace;
        Surgeon = new SurgeonView([], [], last.Surgeon.Faults); // no hands or pedals run; the faults stay readable
        _events = last.EventsAfter(0);
    }

    public SessionStatus Status { get; }

    public IReadOnlyList<ControllerView> Controllers => [];

    public SignalRing Signals { get; } = new([], [], 2);

    public IReadOnlyList<ComponentTiming> Timings => [];

    public RobotModelView Model { get; }

    public SurgeonView Surgeon { get; }

    public WorkspaceView Workspace { get; }

    public Task<CommandResult> SetScaleAsync(string arm, double ratio) => Refused();

    public void NoteCommand(string who, string what)
    {
        // no session runs: nothing is recorded
    }

    public string? RecordingFile => null;

    public Task<CommandResult> RecordAsync(bool on) => Refused();

    public IReadOnlyList<EventEntry> EventsAfter(long after) => [.. _events.Where(e => e.Sequence > after)];

    /// <summary>Nothing runs: the motors of the session that ran went off when it closed.</summary>
    public void StopMotorsNow(string reason)
    {
    }

    /// <summary>How the last session ended, once it has closed: its events then include the stop's read-back.</summary>
    public void Ended(SessionEnd end)
    {
        ArgumentNullException.ThrowIfNull(end);
        _events = end.Events;
        _end = end;
    }

    /// <summary>How the last session ended (before it has finished closing: its last status, without a read-back).</summary>
    public SessionEnd Close() => _end ?? new SessionEnd(Status, null, _events, []);

    public Task<CommandResult> DiscoverAsync() => Refused();

    public Task<CommandResult> RenameAsync(int controllerId, string name) => Refused();

    public Task<CommandResult> ReloadParametersAsync(int controllerId) => Refused();

    public Task<CommandResult> RebootAsync(int controllerId) => Refused();

    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value) => Refused();

    public Task<CommandResult> JogAsync(string motor, double degPerS) => Refused();

    public Task<CommandResult> SetpointAsync(string motor, double deg) => Refused();

    public Task<CommandResult> ReleaseAsync(string motor) => Refused();

    public Task<CommandResult> TorqueAsync(bool on) => Refused();

    public Task<CommandResult> PedalAsync(bool down) => Refused();

    public Task<CommandResult> EmergencyStopAsync() => Task.FromResult(CommandResult.Ok("no graph runs: the motors are off"));

    public Task<CommandResult> HomeAsync(string? motor) => Refused();

    public Task<CommandResult> ClearFaultsAsync() => Refused();

    public void Dispose()
    {
    }

    private static Task<CommandResult> Refused() => Task.FromResult(CommandResult.Fail(CommandOutcome.Refused, Refusal));
}
