using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.WebConsole.Adapter;

/// <summary>The session thread's module work between bus cycles: each module's parameters once, then status polls in turn.</summary>
public sealed partial class HeadlessSession
{
    /// <summary>
    /// Reads a module's parameters; when the module does not answer (noise, a reset, a module gone silent), the read is
    /// tried again on a later turn, up to <see cref="ParameterReadTries"/> times, and the event log says so. A module
    /// that never answers leaves its parameters unknown; the session goes on.
    /// </summary>
    private void TryReadParameters(RobotController c)
    {
        try
        {
            ReadParameters(c);
        }
        catch (IOException ex)
        {
            var tries = _parameterTries[c.Id] = _parameterTries.GetValueOrDefault(c.Id) + 1;
            if (tries < ParameterReadTries)
            {
                _pendingReads.Enqueue(c);
                _events.Add(Now, "bus", $"{ex.Message}; reading module {c.Id}'s parameters again later (try {tries} of {ParameterReadTries})");
            }
            else
            {
                _events.Add(Now, "bus", $"{ex.Message}; module {c.Id}'s parameters stay unknown after {tries} tries (reload them from the bus page)");
            }
        }
    }

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

    /// <summary>Reads the status of the next present module (round robin).</summary>
    private void PollNextModule()
    {
        var controllers = _bus.Controllers;
        for (var n = 0; n < controllers.Count; n++)
        {
            var c = controllers[_pollNext++ % controllers.Count];
            if (!c.Present)
            {
                continue;
            }

            try
            {
                _status[c.Id] = ModuleStatus.Read(_bus, c);
            }
            catch (IOException)
            {
                // A module that stops answering is reported by the bus cycles; keep its last status.
            }

            return;
        }
    }
}
