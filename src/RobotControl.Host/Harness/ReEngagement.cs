using RobotControl.Host.Safety;
using RobotControl.Runtime.Robot;

namespace RobotControl.Host.Harness;

/// <summary>
/// The harness as the surgeon, for a graph without a pedal wired to the robot node: when a soft trip (a short host
/// stall, the master timeout, a jump at the master) has put the run back at PEDAL_UP, it presses the pedal again once
/// the run level has stayed there for <see cref="RunOptions.ReEngageAfter"/>, as a surgeon would after a hiccup. A press
/// refused (the master's data still stale) is tried again after the same delay. Polled after each bus cycle (virtual)
/// or every few milliseconds (real time); E_STOP and INIT are left alone: leaving them is the operator's decision.
/// </summary>
internal sealed class ReEngagement
{
    private readonly SafetySupervisor _supervisor;
    private readonly TimeProvider _clock;
    private readonly TimeSpan? _after;
    private long _upSince = -1;

    public ReEngagement(SafetySupervisor supervisor, TimeProvider clock, TimeSpan? after, bool pedalWired)
    {
        _supervisor = supervisor;
        _clock = clock;
        _after = pedalWired ? null : after;
    }

    /// <summary>Presses made after a soft trip.</summary>
    public int Presses { get; private set; }

    /// <summary>Presses refused (the master's data stale), each tried again later.</summary>
    public int Refused { get; private set; }

    /// <summary>True when the graph wires a pedal to the robot node: the operator's pedal decides, never the harness.</summary>
    public static bool PedalWired(Runtime.GraphFiles.LoadedGraph graph) =>
        graph.Document.Wires.Any(w => w.To == $"{RobotNode.InstanceName}.pedal");

    public void Poll()
    {
        if (_after is not { } after || _supervisor.Level != RunLevel.PedalUp)
        {
            _upSince = -1;
            return;
        }

        var now = _clock.GetTimestamp();
        if (_upSince < 0)
        {
            _upSince = now;
            return;
        }

        if (_clock.GetElapsedTime(_upSince, now) < after)
        {
            return;
        }

        try
        {
            _supervisor.PedalDown("harness");
            Presses++;
        }
        catch (Exception ex) when (ex is InvalidOperationException or IOException)
        {
            Refused++;
            _upSince = now; // the level says why (e.g. the master's data is stale, the bus link failed); try again after another delay
        }
    }
}
