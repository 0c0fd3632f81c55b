using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Safety;

/// <summary>Records a trip (the supervisor's): the check, what it concerns, the value against its limit, the time.</summary>
internal delegate void TripRecorder(SafetyCheck check, string joint, double measured, double limit, string unit, long now);

/// <summary>
/// The supervisor's per-motor checks, each cycle on the bus thread: non-finite feedback at once; tracking error (while
/// driven), current above its fraction of the limit, and pot against encoder (once homed) when they persist for their
/// time. Owns the motors' limits and how long each has been beyond one; allocation-free while nothing trips.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class MotorChecks
{
    private readonly BusRobot _robot;
    private readonly SafetyLimits _limits;
    private readonly TripRecorder _trip;
    private readonly RobotMotor[] _motors;
    private readonly string[] _names;
    private readonly double[] _trackingLimit;
    private readonly double[] _potLimit;
    private readonly long[] _trackingSince;
    private readonly long[] _currentSince;
    private readonly long[] _potSince;
    private readonly long _trackingTicks;
    private readonly long _currentTicks;
    private readonly long _potTicks;

    public MotorChecks(BusRobot robot, SafetyLimits limits, TripRecorder trip)
    {
        _robot = robot;
        _limits = limits;
        _trip = trip;
        _motors = [.. robot.Motors];
        _names = [.. _motors.Select(m => m.Config.FullName)];
        _trackingLimit = [.. _names.Select(limits.TrackingErrorRadOf)];
        _potLimit = [.. _names.Select(limits.PotDistanceRadOf)];
        _trackingSince = new long[_motors.Length];
        _currentSince = new long[_motors.Length];
        _potSince = new long[_motors.Length];
        var f = robot.Client.Time.TimestampFrequency;
        _trackingTicks = (long)(limits.TrackingErrorMs * 1e-3 * f);
        _currentTicks = (long)(limits.OverCurrentMs * 1e-3 * f);
        _potTicks = (long)(limits.PotMismatchMs * 1e-3 * f);
    }

    /// <summary>Motors checked.</summary>
    public int Count => _motors.Length;

    /// <summary>Every motor's checks for this cycle: <paramref name="driven"/> (motors on), <paramref name="homed"/> (positions trusted).</summary>
    public void Check(bool driven, bool homed, long now)
    {
        for (var i = 0; i < _motors.Length; i++)
        {
            CheckMotor(i, driven, homed, now);
        }
    }

    /// <summary>
    /// Takes <paramref name="gap"/> ticks of a host stall (its part beyond the stall limit) out of how long each motor
    /// has been beyond a limit: nothing was observed meanwhile, so a condition seen just before a long stall must
    /// persist for its time after it again; a cycle only slightly late (a bus slowed by timeouts) still counts nearly whole.
    /// </summary>
    public void Discount(long gap)
    {
        Discount(_trackingSince, gap);
        Discount(_currentSince, gap);
        Discount(_potSince, gap);
    }

    /// <summary>Motors whose pot does not confirm the encoder position read with it (no reading, or beyond the pot limit).</summary>
    public int PotsNotConfirming()
    {
        var count = 0;
        for (var i = 0; i < _motors.Length; i++)
        {
            var distance = Math.Abs(_motors[i].PotPositionRad - _motors[i].PositionAtPotRad);
            count += distance <= _potLimit[i] ? 0 : 1; // NaN (no reading) does not confirm
        }

        return count;
    }

    /// <summary>Forgets how long each motor has been beyond a limit (an operator's reset).</summary>
    public void Clear()
    {
        Array.Clear(_trackingSince);
        Array.Clear(_currentSince);
        Array.Clear(_potSince);
    }

    private void CheckMotor(int i, bool driven, bool homed, long now)
    {
        var m = _motors[i];
        var position = m.PositionRad;
        var current = m.CurrentA;
        if (!double.IsFinite(position) || !double.IsFinite(current))
        {
            _trip(SafetyCheck.NonFinite, _names[i], double.IsFinite(position) ? current : position, 0, double.IsFinite(position) ? "A" : "rad", now);
            return;
        }

        var error = Math.Abs(_robot.SentGoalRad(m) - position);
        Persist(ref _trackingSince[i], driven && error > _trackingLimit[i], now, _trackingTicks, SafetyCheck.TrackingError, i, error, _trackingLimit[i], "rad");
        var limit = _limits.CurrentLimitFraction * m.CurrentLimitA;
        Persist(ref _currentSince[i], Math.Abs(current) > limit, now, _currentTicks, SafetyCheck.OverCurrent, i, Math.Abs(current), limit, "A");

        // Pot against encoder once the positions are trusted (after homing); the pot is read at the pot poll's rate, and
        // compared with the encoder position of the same poll.
        var pot = m.PotPositionRad;
        var distance = Math.Abs(pot - m.PositionAtPotRad); // both sampled at the pot poll: a moving joint's pot is not a poll behind
        Persist(ref _potSince[i], homed && double.IsFinite(pot) && distance > _potLimit[i], now, _potTicks, SafetyCheck.PotMismatch, i, distance, _potLimit[i], "rad");
    }

    private void Persist(ref long since, bool beyond, long now, long allowed, SafetyCheck check, int motor, double measured, double limit, string unit)
    {
        if (!beyond)
        {
            since = 0;
            return;
        }

        if (since == 0)
        {
            since = now;
        }

        if (now - since >= allowed)
        {
            _trip(check, _names[motor], measured, limit, unit, now);
        }
    }

    private static void Discount(long[] since, long gap)
    {
        for (var i = 0; i < since.Length; i++)
        {
            if (since[i] != 0)
            {
                since[i] += gap;
            }
        }
    }
}
