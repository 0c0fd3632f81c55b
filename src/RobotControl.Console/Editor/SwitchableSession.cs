using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// The session the endpoints and pages see: it forwards every member to the current session, which the graph editor
/// replaces (stop one graph, start another). A page's request goes to whichever session is current when it arrives.
/// </summary>
public sealed class SwitchableSession : IConsoleSession
{
    private readonly Lock _gate = new();
    private volatile IConsoleSession _current;
    private bool _closed;

    /// <summary>Starts with <paramref name="initial"/> (owned from now on).</summary>
    public SwitchableSession(IConsoleSession initial)
    {
        ArgumentNullException.ThrowIfNull(initial);
        _current = initial;
    }

    /// <summary>The session requests go to now.</summary>
    public IConsoleSession Current => _current;

    /// <inheritdoc />
    public SessionStatus Status => _current.Status;

    /// <inheritdoc />
    public IReadOnlyList<ControllerView> Controllers => _current.Controllers;

    /// <inheritdoc />
    public SignalRing Signals => _current.Signals;

    /// <inheritdoc />
    public IReadOnlyList<ComponentTiming> Timings => _current.Timings;

    /// <inheritdoc />
    public RobotModelView Model => _current.Model;

    /// <inheritdoc />
    public SurgeonView Surgeon => _current.Surgeon;

    /// <inheritdoc />
    public WorkspaceView Workspace => _current.Workspace;

    /// <inheritdoc />
    public Task<CommandResult> SetScaleAsync(string arm, double ratio) => _current.SetScaleAsync(arm, ratio);

    /// <inheritdoc />
    public void NoteCommand(string who, string what) => _current.NoteCommand(who, what);

    /// <inheritdoc />
    public string? RecordingFile => _current.RecordingFile;

    /// <inheritdoc />
    public Task<CommandResult> RecordAsync(bool on) => _current.RecordAsync(on);

    /// <summary>Makes <paramref name="next"/> current and returns the one it replaces (the caller disposes it).</summary>
    public IConsoleSession Replace(IConsoleSession next)
    {
        ArgumentNullException.ThrowIfNull(next);
        lock (_gate)
        {
            if (_closed)
            {
                next.Dispose(); // the console is stopping: nothing new runs, its motors go off with it
                throw new InvalidOperationException("the console is stopping: no graph starts now");
            }

            return Interlocked.Exchange(ref _current, next);
        }
    }

    /// <inheritdoc />
    public IReadOnlyList<EventEntry> EventsAfter(long after) => _current.EventsAfter(after);

    /// <inheritdoc />
    public Task<CommandResult> DiscoverAsync() => _current.DiscoverAsync();

    /// <inheritdoc />
    public Task<CommandResult> RenameAsync(int controllerId, string name) => _current.RenameAsync(controllerId, name);

    /// <inheritdoc />
    public Task<CommandResult> ReloadParametersAsync(int controllerId) => _current.ReloadParametersAsync(controllerId);

    /// <inheritdoc />
    public Task<CommandResult> RebootAsync(int controllerId) => _current.RebootAsync(controllerId);

    /// <inheritdoc />
    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value) => _current.WriteParameterAsync(motor, parameter, value);

    /// <inheritdoc />
    public Task<CommandResult> JogAsync(string motor, double degPerS) => _current.JogAsync(motor, degPerS);

    /// <inheritdoc />
    public Task<CommandResult> SetpointAsync(string motor, double deg) => _current.SetpointAsync(motor, deg);

    /// <inheritdoc />
    public Task<CommandResult> ReleaseAsync(string motor) => _current.ReleaseAsync(motor);

    /// <inheritdoc />
    public Task<CommandResult> TorqueAsync(bool on) => _current.TorqueAsync(on);

    /// <inheritdoc />
    public Task<CommandResult> PedalAsync(bool down) => _current.PedalAsync(down);

    /// <inheritdoc />
    public Task<CommandResult> EmergencyStopAsync() => _current.EmergencyStopAsync();

    /// <inheritdoc />
    public Task<CommandResult> HomeAsync(string? motor) => _current.HomeAsync(motor);

    /// <inheritdoc />
    public Task<CommandResult> ClearFaultsAsync() => _current.ClearFaultsAsync();

    /// <inheritdoc />
    public void StopMotorsNow(string reason) => _current.StopMotorsNow(reason);

    /// <inheritdoc />
    public SessionEnd Close()
    {
        IConsoleSession current;
        lock (_gate)
        {
            _closed = true; // from here on no graph replaces the one closing
            current = _current;
        }

        return current.Close();
    }

    /// <inheritdoc />
    public void Dispose() => _current.Dispose();
}
