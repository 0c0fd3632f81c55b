using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// What the pages see after the graph editor stopped the graph: the last status with the session <c>stopped</c>, no
/// controllers and no signals; every command is refused until a graph starts again.
/// </summary>
internal sealed class StoppedSession : RobotlessSession
{
    private volatile IReadOnlyList<EventEntry> _events;
    private volatile SessionEnd? _end;

    /// <summary>What is left of <paramref name="last"/>: its status (stopped), robot model, workspace, events and faults.</summary>
    public StoppedSession(IConsoleSession last)
        : base("no graph runs: start one from the graph editor")
    {
        ArgumentNullException.ThrowIfNull(last);
        Status = last.Status with { Session = "stopped", TorqueOn = false, RobotState = "INIT", RobotLayer = "Disabled", ModulesFound = 0 };
        Model = last.Model;
        Workspace = last.Workspace;
        Surgeon = new SurgeonView([], [], last.Surgeon.Faults); // no hands or pedals run; the faults stay readable
        _events = last.EventsAfter(0);
    }

    public override SessionStatus Status { get; }

    public override SignalRing Signals { get; } = new([], [], 2);

    public override RobotModelView Model { get; }

    public override SurgeonView Surgeon { get; }

    public override WorkspaceView Workspace { get; }

    public override IReadOnlyList<EventEntry> EventsAfter(long after) => [.. _events.Where(e => e.Sequence > after)];

    /// <summary>How the last session ended, once it has closed: its events then include the stop's read-back.</summary>
    public void Ended(SessionEnd end)
    {
        ArgumentNullException.ThrowIfNull(end);
        _events = end.Events;
        _end = end;
    }

    /// <summary>How the last session ended (before it has finished closing: its last status, without a read-back).</summary>
    public override SessionEnd Close() => _end ?? new SessionEnd(Status, null, _events, []);

    public override Task<CommandResult> EmergencyStopAsync() => Task.FromResult(CommandResult.Ok("no graph runs: the motors are off"));

}
