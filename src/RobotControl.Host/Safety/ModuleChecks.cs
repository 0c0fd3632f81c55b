using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Safety;

/// <summary>
/// The supervisor's per-module checks, each cycle on the bus thread: a module silent for longer than its limit, and,
/// while the motors are on, a bus watchdog not armed with the robot file's period as the status poll reads it back (a
/// module without one would drive on after the host stops). Owns when each module last answered.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ModuleChecks
{
    private readonly RobotController[] _controllers;
    private readonly string[] _names;
    private readonly long[] _answeredAt;
    private readonly long _silentTicks;
    private readonly double _silentMs;
    private readonly int _watchdogMs;
    private readonly long _frequency;
    private readonly TripRecorder _trip;

    public ModuleChecks(BusRobot robot, SafetyLimits limits, TripRecorder trip)
    {
        _controllers = [.. robot.Controllers];
        _names = [.. _controllers.Select(c => $"{ArmName(robot, c)}.{c.Definition.Location}")];
        _answeredAt = new long[_controllers.Length];
        var f = robot.Client.Time.TimestampFrequency;
        _silentTicks = (long)(limits.ModuleSilentMs * 1e-3 * f);
        _silentMs = limits.ModuleSilentMs;
        _watchdogMs = robot.Definition.Modules.WatchdogMs;
        _frequency = f;
        _trip = trip;
    }

    /// <summary>Every module's silence.</summary>
    public void CheckSilence(long now)
    {
        for (var i = 0; i < _controllers.Length; i++)
        {
            var silent = SilentFor(i, now);
            if (silent == 0)
            {
                _answeredAt[i] = now;
            }
            else if (silent > _silentTicks)
            {
                _trip(SafetyCheck.ModuleSilent, _names[i], Ms(silent), _silentMs, "ms", now);
            }
        }
    }

    /// <summary>The first module silent for longer than its limit at <paramref name="now"/>, with how long (ms); null: none.</summary>
    public (string Module, double Ms)? Silent(long now)
    {
        for (var i = 0; i < _controllers.Length; i++)
        {
            if (SilentFor(i, now) is var silent && silent > _silentTicks)
            {
                return (_names[i], Ms(silent));
            }
        }

        return null;
    }

    /// <summary>Every module's armed watchdog (call while the motors are on).</summary>
    public void CheckWatchdogs(long now)
    {
        for (var i = 0; i < _controllers.Length; i++)
        {
            var read = _controllers[i].BusWatchdogMs;
            if (read >= 0 && read != _watchdogMs)
            {
                _trip(SafetyCheck.WatchdogUnarmed, _names[i], read, _watchdogMs, "ms", now);
            }
        }
    }

    /// <summary>How long module <paramref name="i"/> has been silent at <paramref name="now"/>, ticks (0: it answered in the last cycle, or was never timed).</summary>
    private long SilentFor(int i, long now) => _controllers[i].MissedReplies != 0 && _answeredAt[i] != 0 ? now - _answeredAt[i] : 0;

    private double Ms(long ticks) => ticks * 1e3 / _frequency;

    private static string ArmName(BusRobot robot, RobotController c) =>
        c.Definition.Arm >= 0 && c.Definition.Arm < robot.Definition.Arms.Count ? robot.Definition.Arms[c.Definition.Arm].Name : "?";
}
