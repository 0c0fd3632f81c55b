using RobotControl.Host.Safety;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// Copies the safety supervisor's new run-level changes and trips into the session's event log, each once, in order.
/// <para>
/// Written by the status thread (each turn) and by the bus's owner (a command that changed the run level logs it at
/// once); the counts of what is logged already are kept under a lock.
/// </para>
/// </summary>
internal sealed class RunLevelLog(SafetySupervisor supervisor, SessionEvents events)
{
    private readonly Lock _gate = new();
    private int _levelsLogged;
    private int _tripsLogged;

    /// <summary>Logs the run-level changes and trips since the last call.</summary>
    public void CatchUp()
    {
        lock (_gate)
        {
            var history = supervisor.History;
            for (; _levelsLogged < history.Count; _levelsLogged++)
            {
                var h = history[_levelsLogged];
                events.Add("safety", $"{h.From.Name()} -> {h.To.Name()} ({h.Source}): {h.Reason}");
            }

            var trips = supervisor.Trips;
            for (; _tripsLogged < trips.Count; _tripsLogged++)
            {
                events.Add("safety", $"trip: {trips[_tripsLogged]}");
            }
        }
    }
}
