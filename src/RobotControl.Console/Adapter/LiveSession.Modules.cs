using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>The modules' parameters as the bus page shows them: read once per module, between bus cycles, one module at a time.</summary>
public sealed partial class LiveSession
{
    /// <summary>
    /// The status thread's turn: when no read is under way, the next module waiting has its parameters read between
    /// bus cycles (a piece of work of its own, so a cycle waits for one module's reads at most). A module that does not
    /// answer (noise, a reset, a module gone silent) is tried again on a later turn, up to
    /// <see cref="ParameterReadTries"/> times, and the event log says so; after that its parameters stay unknown and
    /// the session goes on.
    /// </summary>
    private void ReadPendingParameters()
    {
        if (_parameterRead is { IsCompleted: false } || !_pendingReads.TryDequeue(out var c))
        {
            return;
        }

        _parameterRead = _commands.Submit(() =>
        {
            ReadParameters(c);
            return CommandResult.Ok($"module {c.Id}: parameters read");
        }).ContinueWith(t => ParametersRead(c, t.Result), TaskScheduler.Default);
    }

    private CommandResult ParametersRead(RobotController c, CommandResult result)
    {
        if (result.Succeeded)
        {
            return result;
        }

        var tries = _parameterTries[c.Id] = _parameterTries.GetValueOrDefault(c.Id) + 1;
        if (tries < ParameterReadTries)
        {
            _pendingReads.Enqueue(c);
            _events.Add(Now, "bus", $"{result.Message}; reading module {c.Id}'s parameters again later (try {tries} of {ParameterReadTries})");
        }
        else
        {
            _events.Add(Now, "bus", $"{result.Message}; module {c.Id}'s parameters stay unknown after {tries} tries (reload them from the bus page)");
        }

        return result;
    }

    /// <summary>Reads a module's parameters (the bus's owner).</summary>
    private void ReadParameters(RobotController c)
    {
        foreach (var m in c.Motors)
        {
            foreach (var p in MotorParameter.All)
            {
                _parameters[(c.Id, m.Config.Channel, p.Key)] = p.FromCounts(m.Config, _bus.ReadParameter(c.Id, p.Field.Name, m.Config.Channel));
            }
        }
    }
}
