using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Robot;

namespace RobotControl.Host.Safety;

/// <summary>
/// What the supervisor watches of the graph that drives the robot, from the bus thread: where the loop's ticks spend
/// their time (<see cref="TickProfile"/>: a late loop's trip names the plug-in it waits for, with no allocation) and
/// whether the robot node holds because a plug-in upstream of it faulted (a trip naming the plug-in and what it threw).
/// It also times the loop (<see cref="CheckLoop"/>). Without a graph (a supervisor on its own) it names the loop only.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class GraphWatch
{
    private readonly GraphProgram? _program;
    private readonly RobotNode? _node;
    private readonly StallClock _clock;
    private readonly TripRecorder _trip;
    private readonly double _periodMs;
    private bool _faultSeen;

    public GraphWatch(StallClock clock, TripRecorder trip, GraphProgram? program = null, RobotNode? node = null, double periodMs = 0)
    {
        _clock = clock;
        _trip = trip;
        _program = program;
        _node = node;
        _periodMs = periodMs;
    }

    /// <summary>
    /// The loop behind, named by the plug-in it waits for. While it drives the arms (PEDAL_DOWN): its last tick older
    /// than the stall limit (a tick that overran or hangs) is a soft trip, graded as a silence (from the modules'
    /// torque-off stage on, the motors go off). While the arms hold (PEDAL_UP), only a loop dead for the torque-off
    /// stage trips, taking the motors off: a dead loop no longer hears the operator's pedals, and the bus thread's
    /// cycle would otherwise keep feeding the modules' watchdogs on its own.
    /// </summary>
    public void CheckLoop(long now, RunLevel level)
    {
        var lag = _clock.LoopLagAt(now, level);
        if (lag > (level == RunLevel.PedalDown ? _clock.StallTicks : _clock.TorqueOffStageTicks))
        {
            _trip(SafetyCheck.DeadlineMiss, Culprit(), _clock.Ms(lag), _clock.Ms(_clock.StallTicks), "ms", now);
        }
    }

    /// <summary>The plug-in a late loop waits for (in its tick now, else the slowest of the last tick if it took a loop period or more), or <c>loop</c>.</summary>
    public string Culprit() => _program?.Profile.Culprit(_periodMs) ?? "loop";

    /// <summary>
    /// Once, when the robot node first holds for a fault upstream: the plug-in and what it threw (allocates then only);
    /// null otherwise.
    /// </summary>
    public (string PlugIn, string What)? NewUpstreamFault()
    {
        if (_faultSeen || _node is not { Holding: true } || _program is null)
        {
            return null;
        }

        _faultSeen = true;
        var faults = _program.Faults;
        if (faults.Count == 0)
        {
            return ("plug-in", "a plug-in upstream of the robot faulted");
        }

        var first = faults[0];
        var names = string.Join(", ", faults.Select(f => $"'{f.Instance}'").Distinct());
        return ($"plug-in '{first.Instance}'", $"plug-in {names} faulted at tick {first.TickIndex} ({first.Message}); it is no longer ticked and the arms hold");
    }
}
