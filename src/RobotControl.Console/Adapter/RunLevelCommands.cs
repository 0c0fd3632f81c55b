using System.Diagnostics;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console's commands on the run level: torque, pedal, clear faults, run by the bus's owner between cycles; and
/// the emergency stop, which is not a command: it goes to the supervisor directly from the caller's thread.
/// <para>Holds no state of its own: the run level is the supervisor's; what changed is logged at once (<see cref="RunLevelLog"/>).</para>
/// </summary>
internal sealed class RunLevelCommands(SafetySupervisor supervisor, BusRobot bus, CommandQueue queue, SessionEvents events, RunLevelLog runLevels, SessionThreadState sessionThread)
{
    /// <summary>How long an emergency stop's caller waits to see the run level at E_STOP before it is told it is not yet.</summary>
    private static readonly TimeSpan EmergencyStopConfirmation = TimeSpan.FromSeconds(1);

    /// <inheritdoc cref="IConsoleSession.TorqueAsync"/>
    public Task<CommandResult> TorqueAsync(bool on) => queue.Submit(() =>
    {
        if (!on)
        {
            supervisor.MotorsOff("console");
            runLevels.CatchUp();
            return CommandResult.Ok($"motors off (run level {supervisor.Level.Name()})");
        }

        if (supervisor.Level is RunLevel.PedalUp or RunLevel.PedalDown)
        {
            return CommandResult.Ok($"the motors are on already (run level {supervisor.Level.Name()})");
        }

        if (supervisor.Level == RunLevel.EStop)
        {
            return CommandResult.Fail(CommandOutcome.Refused, "the run level is E_STOP: clear faults (an operator reset) first, then turn torque on");
        }

        try
        {
            var homed = supervisor.Home("console");
            runLevels.CatchUp();
            return CommandResult.Ok(homed.Count == 0 ? "motors on, holding (run level PEDAL_UP)" : $"{homed.Count} motors homed; motors on, holding (run level PEDAL_UP)");
        }
        catch (InvalidOperationException ex)
        {
            runLevels.CatchUp();
            return CommandResult.Fail(CommandOutcome.Refused, $"torque on: {ex.Message}");
        }
    });

    /// <inheritdoc cref="IConsoleSession.PedalAsync"/>
    public Task<CommandResult> PedalAsync(bool down) => queue.Submit(() =>
    {
        if (!down)
        {
            supervisor.PedalUp("console");
            runLevels.CatchUp();
            return CommandResult.Ok($"pedal up: holding (run level {supervisor.Level.Name()})");
        }

        try
        {
            supervisor.PedalDown("console");
        }
        catch (InvalidOperationException ex)
        {
            return CommandResult.Fail(CommandOutcome.Refused, $"{ex.Message}: turn torque on first");
        }

        runLevels.CatchUp();
        return CommandResult.Ok("pedal down: the arms follow the graph and the console's jogs (run level PEDAL_DOWN)");
    });

    /// <inheritdoc cref="IConsoleSession.EmergencyStopAsync"/>
    /// <remarks>
    /// Not a queued command: the supervisor's emergency stop is lock-free from this thread and overtakes any queued
    /// work; the result says when the run level is E_STOP (the hold or the motors off is then on the wire).
    /// </remarks>
    public async Task<CommandResult> EmergencyStopAsync()
    {
        supervisor.EmergencyStop("console", "operator's emergency stop on the console");
        var waited = Stopwatch.StartNew();
        while (supervisor.Level != RunLevel.EStop && waited.Elapsed < EmergencyStopConfirmation)
        {
            await Task.Delay(1).ConfigureAwait(false);
        }

        return supervisor.Level == RunLevel.EStop
            ? CommandResult.Ok($"emergency stop: run level {supervisor.Level.Name()}; clear faults to reset")
            : CommandResult.Fail(CommandOutcome.Failed, $"emergency stop asked for; the run level is still {supervisor.Level.Name()} after {EmergencyStopConfirmation.TotalSeconds:0} s: the bus cycle is not running ({sessionThread.Phase})");
    }

    /// <inheritdoc cref="IConsoleSession.ClearFaultsAsync"/>
    public Task<CommandResult> ClearFaultsAsync() => queue.Submit(() =>
    {
        bus.ClearFaults();
        if (supervisor.Level == RunLevel.EStop)
        {
            supervisor.Reset("console");
            runLevels.CatchUp();
            events.Add("console", "faults cleared; E_STOP reset to INIT");
            return CommandResult.Ok("faults cleared; run level INIT: turn torque on to home and hold");
        }

        events.Add("console", "faults cleared");
        return CommandResult.Ok("faults cleared");
    });
}
