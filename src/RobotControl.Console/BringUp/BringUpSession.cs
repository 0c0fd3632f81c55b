using RobotControl.Robot.Calibration;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// The console without a robot session that brings a unit up (<c>robotctl console --bring-up</c>): the unit's state
/// from its unit file (<see cref="UnitView"/>), and the two steps, Commission and Calibrate pots, run on the server one
/// at a time (<see cref="BringUpJob"/>), their progress lines numbered for the page. Starting a step and Continue need
/// the operator role (the endpoints check it); <see cref="StopAsync"/>, the page's STOP, and the status bar's E-STOP
/// stop the step for every console: the calibrator turns its module's motors off (read back) before the answer. Every
/// robot-session command is refused: there is no running robot.
/// </summary>
public sealed class BringUpSession : RobotlessSession
{
    /// <summary>How long a stop waits for the step to confirm its motors off before it answers without it.</summary>
    public static readonly TimeSpan StopWait = TimeSpan.FromSeconds(30);

    private readonly BringUpSetup _setup;
    private readonly Lock _gate = new();
    private readonly List<EventEntry> _events = [];
    private readonly long _started;
    private BringUpJob? _job;

    /// <summary>A bring-up console for <paramref name="setup"/>'s unit.</summary>
    public BringUpSession(BringUpSetup setup)
        : base("bring-up console: no robot session runs; use the Bring-up page (or robotctl console <graph> once the unit is brought up)")
    {
        ArgumentNullException.ThrowIfNull(setup);
        _setup = setup;
        _started = setup.Time.GetTimestamp();
    }

    /// <summary>Every step's progress lines, numbered across the session.</summary>
    public ProgressLines Lines { get; } = new();

    /// <summary>The step running or last run, or null.</summary>
    public BringUpJob? Job => _job;

    /// <summary>The unit as its file has it now.</summary>
    public UnitView Unit => UnitView.Read(_setup);

    /// <summary>Starts commissioning (<paramref name="poll"/>: wait for each module instead of for Continue).</summary>
    public CommandResult StartCommission(bool poll) =>
        Start("commission", $"Commission unit {_setup.Unit} on {_setup.Transport}{(poll ? ", waiting for each module" : string.Empty)}", (prompt, stop) => BringUpSteps.Commission(_setup, poll, Lines, prompt, stop));

    /// <summary>Starts the pot calibration of module <paramref name="moduleId"/> (null: every module).</summary>
    public CommandResult StartCalibration(int? moduleId, bool redo)
    {
        string? joints = null;
        if (moduleId is { } id)
        {
            var module = _setup.Robot.Modules.Modules.FirstOrDefault(m => m.Id == id);
            if (module is null)
            {
                return CommandResult.Fail(CommandOutcome.NotFound, $"calibrate: the robot file has no module {id} (modules: {string.Join(", ", _setup.Robot.Modules.Modules.Select(m => $"{m.Id} {m.Name}"))})");
            }

            joints = string.Join(',', Unit.Modules.Single(m => m.Id == id).Motors.Select(m => m.Name));
        }

        var what = moduleId is null ? "every module" : $"module {moduleId}";
        return Start("calibrate", $"Calibrate pots of unit {_setup.Unit}, {what}{(redo ? ", again" : string.Empty)}", (prompt, stop) => BringUpSteps.Calibrate(_setup, joints, redo, Lines, prompt, stop));
    }

    /// <summary>The operator's Continue: the step waiting for it goes on.</summary>
    public CommandResult Continue() =>
        _job is { } job && job.Prompt.Continue()
            ? CommandResult.Ok($"{job.Step}: continuing")
            : CommandResult.Fail(CommandOutcome.Refused, "continue: no step is waiting for the operator");

    /// <summary>Stops the running step; answers once it has ended (a calibration: with its motors off, read back) or after <see cref="StopWait"/>.</summary>
    public async Task<CommandResult> StopAsync(string who)
    {
        var job = _job;
        if (job is null || !job.Running)
        {
            return CommandResult.Ok($"{who}: no bring-up step is running; this console drives no motor");
        }

        job.Stop();
        Note("stop", $"{who}: stop asked during {job.Step}");
        if (await Task.WhenAny(job.Ended, Task.Delay(StopWait, _setup.Time)).ConfigureAwait(false) != job.Ended)
        {
            return CommandResult.Fail(CommandOutcome.Failed, $"{who}: {job.Step} has not confirmed its motors off within {StopWait.TotalSeconds:0} s: switch the modules' power off");
        }

        return CommandResult.Ok($"{who}: {job.Outcome}");
    }

    /// <inheritdoc />
    public override SessionStatus Status
    {
        get
        {
            var job = _job;
            // Motors in doubt: a calibration running, or one that ended without its motors confirmed off (the calibrator's
            // own line says "turning its motors off was not confirmed", or an exception its run does not handle).
            var calibrating = job is { Step: "calibrate" } && (job.Running || job.Unexpected || job.Outcome?.Contains(PotCalibrator.NotConfirmedOff, StringComparison.Ordinal) == true);
            var state = job is null ? "bring-up: idle" : $"bring-up: {job.Step} {job.State}";
            var faults = job is { State: "failed" or "stopped", Outcome: { } outcome } ? new[] { outcome } : [];
            var modules = Unit.Modules;
            return new SessionStatus(_setup.Robot.Name, $"bring-up {_setup.Unit}", _setup.Transport, modules.Count, modules.Count(m => m.Commissioned), 0, 0, 0, 0, 0, 0, null,
                _setup.Time.GetElapsedTime(_started).TotalSeconds, "INIT", "Disabled", state, calibrating, faults, 0, new BusCounters(0, 0, 0, 0, 0));
        }
    }

    /// <inheritdoc />
    public override SignalRing Signals { get; } = new([], [], 2);

    /// <inheritdoc />
    public override RobotModelView Model { get; } = new(string.Empty, []);

    /// <inheritdoc />
    public override SurgeonView Surgeon { get; } = new([], [], []);

    /// <inheritdoc />
    public override WorkspaceView Workspace { get; } = new([]);

    /// <inheritdoc />
    public override IReadOnlyList<EventEntry> EventsAfter(long after)
    {
        lock (_gate)
        {
            return [.. _events.Where(e => e.Sequence > after)];
        }
    }

    /// <inheritdoc />
    public override Task<CommandResult> EmergencyStopAsync() => StopAsync("E-STOP");

    /// <inheritdoc />
    public override void StopMotorsNow(string reason) => _job?.Stop();

    /// <inheritdoc />
    public override void NoteCommand(string who, string what) => Note(who, what);

    /// <inheritdoc />
    public override SessionEnd Close()
    {
        if (_job is { } job)
        {
            job.Stop();
            job.Ended.Wait(StopWait);
        }

        return new SessionEnd(Status with { Session = "stopped" }, null, EventsAfter(0), []);
    }

    /// <inheritdoc />
    protected override void Dispose(bool disposing)
    {
        _ = Close();
        _job?.Dispose();

        base.Dispose(disposing);
    }

    private CommandResult Start(string step, string title, Action<OperatorPrompt, CancellationToken> run)
    {
        lock (_gate)
        {
            if (_job is { Running: true } running)
            {
                return CommandResult.Fail(CommandOutcome.Refused, $"{step}: {running.Step} is running; wait for it to end or stop it first");
            }

            Lines.WriteLine($"== {title}");
            _job?.Dispose();
            _job = new BringUpJob(step, Lines, run);
        }

        Note(step, title);
        return CommandResult.Ok($"{title}: started");
    }

    private void Note(string source, string message)
    {
        lock (_gate)
        {
            _events.Add(new EventEntry(_events.Count + 1, _setup.Time.GetElapsedTime(_started).TotalSeconds, source, message));
        }
    }
}
