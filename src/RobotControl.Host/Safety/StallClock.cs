using RobotControl.Robot.Bus;

namespace RobotControl.Host.Safety;

/// <summary>
/// The supervisor's clock of silences: how long since the last bus cycle (a host stall) and since the control loop's
/// last tick (a loop behind), each against the stall limit (<c>deadline_misses_in_a_row</c> loop periods). The last
/// cycle's time is written on the bus thread, only while the motors hold or follow teleoperation (set-up and homing run
/// the bus at their own pace), and read on the loop's (<see cref="OnTime"/>: a tick whose cycle is late holds).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class StallClock
{
    private readonly TimeProvider _time;
    private readonly OperatorInputs _inputs;
    private long _lastCycle;
    private RunLevel _timedLevel;
    private long _timedFrom;

    public StallClock(TimeProvider time, long stallTicks, double torqueOffStageMs, OperatorInputs inputs)
    {
        _time = time;
        StallTicks = stallTicks;
        TorqueOffStageTicks = (long)(torqueOffStageMs * 1e-3 * time.TimestampFrequency);
        _inputs = inputs;
    }

    /// <summary>The stall limit, timestamp ticks.</summary>
    public long StallTicks { get; }

    /// <summary>The modules' torque-off stage, timestamp ticks: they switch their motors off after this much silence.</summary>
    public long TorqueOffStageTicks { get; }

    /// <summary>A cycle at <paramref name="now"/>: the gap since the last timed one (0 for the first); when not <paramref name="timed"/>, timing restarts with the next.</summary>
    public long Cycle(long now, bool timed)
    {
        var last = _lastCycle;
        Volatile.Write(ref _lastCycle, timed ? now : 0);
        return last == 0 ? 0 : now - last;
    }

    /// <summary>Timing restarts with the next cycle (the motors off: nothing to time).</summary>
    public void Restart() => Volatile.Write(ref _lastCycle, 0);

    /// <summary>True when the bus cycled within the stall limit, or is not timed (any thread).</summary>
    public bool OnTime()
    {
        var last = Volatile.Read(ref _lastCycle);
        return last == 0 || _time.GetTimestamp() - last <= StallTicks;
    }

    /// <summary>How long since the loop last ticked, timestamp ticks (0 before its first tick: a loop not started is not behind).</summary>
    public long LoopLag(long now) => _inputs.LastTick is not 0 and var tick ? now - tick : 0;

    /// <summary>
    /// The loop's lag as the checks time it at <paramref name="level"/>: from its last tick, or from when the run level
    /// last changed if that is later (a long piece of set-up between cycles, homing, ends in PEDAL_UP: the loop is timed
    /// from there, not from before it).
    /// </summary>
    public long LoopLagAt(long now, RunLevel level)
    {
        if (level != _timedLevel)
        {
            (_timedLevel, _timedFrom) = (level, now);
        }

        return _inputs.LastTick is not 0 and var tick ? now - Math.Max(tick, _timedFrom) : 0;
    }

    /// <summary><paramref name="ticks"/> in milliseconds.</summary>
    public double Ms(long ticks) => ticks * 1e3 / _time.TimestampFrequency;
}
