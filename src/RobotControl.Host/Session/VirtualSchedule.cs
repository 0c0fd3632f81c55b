using RobotControl.Robot.Bus;
using RobotControl.Runtime.Loop;
using RobotControl.Simulation.Time;

namespace RobotControl.Host.Session;

/// <summary>
/// The deterministic schedule of a virtual session: it owns the loop's clock and calls the cycle's steps
/// (<see cref="IBusCycle"/>) in order, on one thread, nothing nested in anything else:
/// <list type="number">
/// <item><b>read</b> (<see cref="BusRobot.Read"/>): the feedback crosses the virtual wire; the bus clock moves as the
/// bytes take their time and the firmware and motor models run.</item>
/// <item><b>tick</b>: every loop tick whose instant has now passed runs, at that instant (the loop clock is set to
/// it). The feedback just read is not published yet, so a tick sees what was published before its instant.</item>
/// <item><b>publish</b> (<see cref="BusRobot.Publish"/>): the feedback is published and the modules watched (status
/// polls take bus time too), then <b>check</b> (<see cref="BusRobot.Check"/>, the safety supervisor), followed by the
/// ticks that came due meanwhile.</item>
/// <item>one piece of the work between cycles (<see cref="BusRobot.RunBetweenCycles"/>), then <b>write</b>
/// (<see cref="BusRobot.Write"/>): the setpoints the ticks wrote become goals on the wire.</item>
/// </list>
/// The schedule's thread owns the bus while it runs, so set-up asked for from other threads runs between its cycles.
/// This is the deterministic equivalent of a loop thread and a bus thread exchanging latest values: each tick sees
/// and writes exactly what it would at its instant with two threads, whatever a bus cycle costs relative to the loop
/// period. The same robot, graph, faults and seed give the same run.
/// <para>
/// A tick's cost counts against its period, as on the wall clock: a tick (after the first, which starts the graph)
/// whose CPU time on this thread (<see cref="ThreadCpuClock"/>, without time spent compiling) exceeds the period keeps
/// the loop busy for that long on the virtual clock: the loop counts its misses as on its own thread
/// (<see cref="ControlLoop.Overran"/>: k for a tick of k periods and a little more), the ticks due meanwhile are
/// skipped, and the bus cycles on meanwhile, so that the safety supervisor sees the loop fall behind and trips as it would
/// with real threads. A graph too slow for its rate fails on the virtual robot before it reaches a real one; a machine
/// busy with other work does not (the thread's CPU time leaves out the time it waited for a CPU), but a virtual machine
/// whose virtual CPU is held by its host can (<see cref="VirtualTickCost.Measured"/>). With
/// <see cref="VirtualTickCost.Free"/> ticks take no loop time, and a run is exactly reproducible anywhere.
/// </para>
/// </summary>
public sealed class VirtualSchedule
{
    private readonly IBusCycle _robot;
    private readonly ManualTimeProvider _busClock;
    private readonly ManualTimeProvider _loopClock;
    private readonly ControlLoop _loop;
    private readonly long _ticks;
    private readonly long _period;
    private readonly Action<ControlLoop, long> _tick;
    private long _nextTick;
    private readonly bool _measured;
    private long _busyUntil;

    /// <summary>A schedule of <paramref name="ticks"/> loop ticks from now on <paramref name="busClock"/>.</summary>
    /// <param name="robot">The robot whose cycle steps are called (a <see cref="BusRobot"/>).</param>
    /// <param name="busClock">The virtual bus's clock (moved by the simulation).</param>
    /// <param name="loopClock">The loop's clock (moved by this schedule, to each tick's instant).</param>
    /// <param name="loop">The control loop, stepped once per tick.</param>
    /// <param name="ticks">Ticks to run.</param>
    /// <param name="aroundTick">Runs each tick instead of <see cref="ControlLoop.Step"/> (must call it once), given the tick's timestamp.</param>
    /// <param name="tickCost">Whether a tick's CPU time counts against its period (<see cref="VirtualTickCost.Measured"/>) or ticks take no loop time (<see cref="VirtualTickCost.Free"/>: exactly reproducible).</param>
    public VirtualSchedule(IBusCycle robot, ManualTimeProvider busClock, ManualTimeProvider loopClock, ControlLoop loop, long ticks, Action<ControlLoop, long>? aroundTick = null, VirtualTickCost tickCost = VirtualTickCost.Measured)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(busClock);
        ArgumentNullException.ThrowIfNull(loopClock);
        ArgumentNullException.ThrowIfNull(loop);
        ArgumentOutOfRangeException.ThrowIfNegative(ticks);
        _robot = robot;
        _busClock = busClock;
        _loopClock = loopClock;
        _loop = loop;
        _ticks = ticks;
        _period = loop.Period.Ticks;
        _tick = aroundTick ?? ((l, _) => l.Step());
        if (!Enum.IsDefined(tickCost))
        {
            throw new ArgumentOutOfRangeException(nameof(tickCost), tickCost, "not a tick cost");
        }

        _measured = tickCost == VirtualTickCost.Measured;
        if (_measured && ThreadCpuClock.Available)
        {
            loop.CostClock ??= ThreadCpuClock.NowNs; // the schedule's thread runs the ticks: their CPU time is their cost
        }

        var now = busClock.GetTimestamp();
        loopClock.SetTimestamp(now);
        _nextTick = now + _period;
    }

    /// <summary>
    /// Runs cycles until every tick has run, or <paramref name="stopWhen"/> (checked after each cycle) says stop, in
    /// which case one last write takes up what the last check decided; <paramref name="afterCycle"/> runs after each
    /// (progress, events).
    /// </summary>
    public void Run(Action? afterCycle = null, Func<bool>? stopWhen = null)
    {
        if (_loop.TickCount >= _ticks)
        {
            return;
        }

        using var own = _robot.OwnBus();
        _robot.Write();
        while (true)
        {
            _robot.Read();
            TickDue();
            _robot.Publish();
            _robot.Check();
            TickDue();
            afterCycle?.Invoke();
            if (stopWhen is not null && stopWhen())
            {
                _robot.Write(); // what the last check decided (a hold, the motors off) reaches the wire before the run ends
                return;
            }

            if (_loop.TickCount >= _ticks)
            {
                return;
            }

            _robot.RunBetweenCycles();
            _robot.Write();
        }
    }

    /// <summary>
    /// Runs every tick due by the bus clock's now, each at its own instant on the loop clock; those due while the loop
    /// is still busy with a tick that cost more than its period are skipped, as the loop's thread skips them.
    /// </summary>
    private void TickDue()
    {
        var now = _busClock.GetTimestamp();
        while (_nextTick <= now)
        {
            if (_loop.TickCount < _ticks)
            {
                if (_nextTick >= _busyUntil)
                {
                    Tick(_nextTick); // one due while the loop was still busy is skipped
                }
            }

            _nextTick += _period;
        }
    }

    /// <summary>One tick at <paramref name="due"/>, the graph's CPU time in it (without compiling; not the work a harness does around it, such as an injected stall) counted against the period.</summary>
    private void Tick(long due)
    {
        _loopClock.SetTimestamp(due);
        var measured = _measured && _loop.TickCount > 0 && _loop.CostClock is not null; // the first tick starts the graph (first-time costs)
        _tick(_loop, due);
        if (!measured)
        {
            return;
        }

        var cost = (long)(_loop.LastTickCostNs * 1e-9 * _busClock.TimestampFrequency); // the graph's tick alone, not the harness around it
        if (cost > _period)
        {
            _busyUntil = due + cost;
            _loop.Overran(_busyUntil);
        }
    }
}
