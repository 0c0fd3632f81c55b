using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Safety;

/// <summary>
/// The supervisor's trips, oldest first, and which checks have tripped: a trip once per check until an operator's
/// reset, a soft trip once per check per episode of teleoperation (until the next pedal down), so that a condition
/// that stays true cycle after cycle is recorded, and allocates, once. Recorded on the bus thread; read from any thread
/// (a copy, under its lock).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class TripLog
{
    private readonly List<SafetyTrip> _trips = new(32);
    private readonly Lock _gate = new();
    private int _count;
    private readonly bool[] _tripped = new bool[Enum.GetValues<SafetyCheck>().Length];
    private readonly bool[] _softTripped = new bool[Enum.GetValues<SafetyCheck>().Length];

    /// <summary>Trips so far, read without the lock: a reader that polls copies <see cref="All"/> only when it grew.</summary>
    public int Count => Volatile.Read(ref _count);

    /// <summary>Every trip so far, oldest first (a copy).</summary>
    public IReadOnlyList<SafetyTrip> All
    {
        get
        {
            lock (_gate)
            {
                return [.. _trips];
            }
        }
    }

    /// <summary>Records a trip of <paramref name="check"/> unless it tripped since the last reset; null: already recorded.</summary>
    public SafetyTrip? TryRecord(long now, SafetyCheck check, string joint, double measured, double limit, string unit, SafeState action) =>
        TryRecord(_tripped, now, check, joint, measured, limit, unit, action, soft: false);

    /// <summary>Records a soft trip of <paramref name="check"/> unless one was recorded this episode; null: already recorded.</summary>
    public SafetyTrip? TryRecordSoft(long now, SafetyCheck check, string joint, double measured, double limit, string unit) =>
        TryRecord(_softTripped, now, check, joint, measured, limit, unit, SafeState.Hold, soft: true);

    /// <summary>A new episode of teleoperation (a pedal down): a soft trip of any check is recorded again.</summary>
    public void NewEpisode()
    {
        lock (_gate)
        {
            Array.Clear(_softTripped);
        }
    }

    /// <summary>An operator's reset: every check may trip again (the trips so far stay listed).</summary>
    public void Reset()
    {
        lock (_gate)
        {
            Array.Clear(_tripped);
            Array.Clear(_softTripped);
        }
    }

    private SafetyTrip? TryRecord(bool[] flags, long now, SafetyCheck check, string joint, double measured, double limit, string unit, SafeState action, bool soft)
    {
        lock (_gate)
        {
            if (flags[(int)check])
            {
                return null; // nothing allocated while the same condition goes on
            }

            flags[(int)check] = true;
            var trip = new SafetyTrip(now, check, joint, measured, limit, unit, action, soft);
            _trips.Add(trip);
            Volatile.Write(ref _count, _trips.Count);
            return trip;
        }
    }
}
