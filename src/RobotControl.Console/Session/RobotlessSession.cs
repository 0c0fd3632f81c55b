namespace RobotControl.WebConsole.Session;

/// <summary>
/// A console with no robot session behind it: the graph editor's stopped graph, a replay, a bring-up. Every robot
/// command (discovery, parameters, jogs and setpoints, torque, pedal, homing, fault clearing, scaling, recording) is
/// refused here, once, with the mode's own sentence, so a new command is refused by every such mode at once. Each mode
/// says what an emergency stop does in it (it is never refused) and what the pages show.
/// </summary>
public abstract class RobotlessSession : IConsoleSession
{
    private readonly Task<CommandResult> _refused;

    /// <param name="refusal">The line every robot command is refused with, saying what to do instead.</param>
    protected RobotlessSession(string refusal)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(refusal);
        Refusal = refusal;
        _refused = Task.FromResult(CommandResult.Fail(CommandOutcome.Refused, refusal));
    }

    /// <summary>The line every robot command is refused with.</summary>
    public string Refusal { get; }

    /// <inheritdoc />
    public abstract SessionStatus Status { get; }

    /// <summary>No robot: no controllers.</summary>
    public IReadOnlyList<ControllerView> Controllers => [];

    /// <inheritdoc />
    public abstract SignalRing Signals { get; }

    /// <summary>No loop runs: nothing is timed.</summary>
    public IReadOnlyList<ComponentTiming> Timings => [];

    /// <inheritdoc />
    public abstract RobotModelView Model { get; }

    /// <inheritdoc />
    public abstract SurgeonView Surgeon { get; }

    /// <inheritdoc />
    public abstract WorkspaceView Workspace { get; }

    /// <summary>No session runs: nothing is being recorded.</summary>
    public string? RecordingFile => null;

    /// <inheritdoc />
    public abstract IReadOnlyList<EventEntry> EventsAfter(long after);

    /// <summary>What an emergency stop does in this mode; never refused.</summary>
    public abstract Task<CommandResult> EmergencyStopAsync();

    /// <summary>Nothing drives a motor unless the mode says otherwise.</summary>
    public virtual void StopMotorsNow(string reason)
    {
    }

    /// <summary>Nothing is recorded unless the mode keeps its own log.</summary>
    public virtual void NoteCommand(string who, string what)
    {
    }

    /// <inheritdoc />
    public abstract SessionEnd Close();

    /// <inheritdoc />
    public void Dispose()
    {
        Dispose(true);
        GC.SuppressFinalize(this);
    }

    /// <inheritdoc />
    public Task<CommandResult> DiscoverAsync() => _refused;

    /// <inheritdoc />
    public Task<CommandResult> RenameAsync(int controllerId, string name) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> ReloadParametersAsync(int controllerId) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> RebootAsync(int controllerId) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> JogAsync(string motor, double degPerS) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> SetpointAsync(string motor, double deg) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> ReleaseAsync(string motor) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> TorqueAsync(bool on) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> PedalAsync(bool down) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> HomeAsync(string? motor) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> ClearFaultsAsync() => _refused;

    /// <inheritdoc />
    public Task<CommandResult> SetScaleAsync(string arm, double ratio) => _refused;

    /// <inheritdoc />
    public Task<CommandResult> RecordAsync(bool on) => _refused;

    /// <summary>Releases what the mode holds (its timer, its running step).</summary>
    protected virtual void Dispose(bool disposing)
    {
    }
}
