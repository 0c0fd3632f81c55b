namespace RobotControl.WebConsole.Session;

/// <summary>
/// What the console needs of a running session, and nothing more: snapshots for the pages, the signal ring for
/// streaming, and commands that the session's bus/loop thread applies between cycles. The endpoints and pages know
/// only this interface; everything about buses, modules and the control loop stays behind it.
/// <para>
/// Snapshot members are cheap and thread-safe (they return the latest published immutable value). Command members
/// validate their arguments first, on the caller's thread: a bad argument gives a <see cref="CommandResult"/> with
/// <see cref="CommandOutcome.BadInput"/> or <see cref="CommandOutcome.NotFound"/> and nothing is queued; a valid command
/// is queued, applied by the session thread and its task completes with what the robot said.
/// </para>
/// </summary>
public interface IConsoleSession : IDisposable
{
    /// <summary>Robot, transport, loop and fault summary.</summary>
    SessionStatus Status { get; }

    /// <summary>The controllers (modules) with their motors, parameters and live values, as last published.</summary>
    IReadOnlyList<ControllerView> Controllers { get; }

    /// <summary>Every streamed signal and its recent history.</summary>
    SignalRing Signals { get; }

    /// <summary>Events (faults, module resets, commands applied) with a sequence number above <paramref name="after"/>.</summary>
    IReadOnlyList<EventEntry> EventsAfter(long after);

    /// <summary>Per-component timing of the session thread and the loop.</summary>
    IReadOnlyList<ComponentTiming> Timings { get; }

    /// <summary>The robot model of the 3D view (URDF plus where each arm sits).</summary>
    RobotModelView Model { get; }

    /// <summary>Pings the bus and compares what answers with the robot file.</summary>
    Task<CommandResult> DiscoverAsync();

    /// <summary>Renames a controller (its friendly name in this session).</summary>
    Task<CommandResult> RenameAsync(int controllerId, string name);

    /// <summary>Re-reads a controller's persistent parameters.</summary>
    Task<CommandResult> ReloadParametersAsync(int controllerId);

    /// <summary>Restarts a controller (its firmware reboots and resumes from FRAM).</summary>
    Task<CommandResult> RebootAsync(int controllerId);

    /// <summary>Writes one persistent parameter of one motor, in the units <see cref="ParameterSpec"/> lists, into FRAM.</summary>
    Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value);

    /// <summary>Jogs a motor at <paramref name="degPerS"/> at its axis output (0 stops and holds).</summary>
    Task<CommandResult> JogAsync(string motor, double degPerS);

    /// <summary>Moves a motor to <paramref name="deg"/> at its axis output.</summary>
    Task<CommandResult> SetpointAsync(string motor, double deg);

    /// <summary>Hands a motor back to the control loop's setpoints.</summary>
    Task<CommandResult> ReleaseAsync(string motor);

    /// <summary>Turns every motor on (homing first where positions are in doubt) or off.</summary>
    Task<CommandResult> TorqueAsync(bool on);

    /// <summary>Presses (down) or releases (up) the pedal: the robot moves (graph, jogs, setpoints) only while it is down.</summary>
    Task<CommandResult> PedalAsync(bool down);

    /// <summary>An operator's emergency stop (leaving it needs <see cref="ClearFaultsAsync"/>).</summary>
    Task<CommandResult> EmergencyStopAsync();

    /// <summary>Homes one motor (<paramref name="motor"/>) or all of them (null) from their pots; the motors must be off.</summary>
    Task<CommandResult> HomeAsync(string? motor);

    /// <summary>Clears latched faults in the robot and its modules; at an emergency stop, resets it (motors off, homing needed).</summary>
    Task<CommandResult> ClearFaultsAsync();

    /// <summary>The surgeon's view: hands (clutch, lock, scale, walls) and pedals found in the graph, faults in plain words.</summary>
    SurgeonView Surgeon { get; }

    /// <summary>The reachable workspace of each arm (sampled once from the robot file's kinematics).</summary>
    WorkspaceView Workspace { get; }

    /// <summary>Sets the scale factor (motion ratio) of an arm's hand; refused unless that hand's clutch is held.</summary>
    Task<CommandResult> SetScaleAsync(string arm, double ratio);

    /// <summary>
    /// The first thing a stop does (a signal to the console), from any thread, lock-free and never waiting: the motors
    /// are asked off at the next bus write, ahead of queued commands; <see cref="Close"/> then reads them back.
    /// </summary>
    void StopMotorsNow(string reason);

    /// <summary>The MCAP file the session is being recorded to now (docs/recording.md), or null.</summary>
    string? RecordingFile { get; }

    /// <summary>Notes an operator command the console answered (who sent it, what it was and the answer) in the session's recording, if it is being recorded; from any thread, never waiting.</summary>
    void NoteCommand(string who, string what);

    /// <summary>Starts recording the session to a new file in its recordings folder, or stops the recording (the record button).</summary>
    Task<CommandResult> RecordAsync(bool on);

    /// <summary>
    /// Ends the session: the loop stops, the motors go off and every module is read back. Once closed, it stays closed
    /// and returns the same end; <see cref="IDisposable.Dispose"/> closes it too.
    /// </summary>
    SessionEnd Close();
}
