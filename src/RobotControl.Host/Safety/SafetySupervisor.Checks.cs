using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Host.Safety;

/// <summary>The per-cycle checks, run inside the bus cycle between read and write; allocation-free while nothing trips.</summary>
public sealed partial class SafetySupervisor
{
    /// <summary>The checks of time alone, just before the write (bus thread): a host stall's or a late loop's hold is taken by this write.</summary>
    void ICycleCheck.BeforeWrite()
    {
        var now = _time.GetTimestamp();
        CheckGap(now);
        if (Level is RunLevel.PedalUp or RunLevel.PedalDown)
        {
            _graph.CheckLoop(now, Level); // before the write that takes the loop's setpoints (on the virtual schedule, after the ticks due)
        }
    }

    /// <summary>The per-cycle checks: step <b>check</b> of the robot's cycle, on the bus thread.</summary>
    void ICycleCheck.Check()
    {
        FollowOperator();
        if (Level == RunLevel.Init)
        {
            _clock.Restart();
            return; // motors off and nothing commanded: the checks start with homing
        }

        var now = _time.GetTimestamp();
        CheckGap(now);
        _moduleChecks.CheckSilence(now);
        if (_robot.State == RobotState.Enabled && Level is RunLevel.PedalUp or RunLevel.PedalDown)
        {
            _moduleChecks.CheckWatchdogs(now);
        }

        if (_robot.State == RobotState.Fault)
        {
            Trip(SafetyCheck.ModuleFault, string.Empty, (double)_robot.Faults, 0, "fault flags", now);
        }
        else if (_robot.ModulesHolding is > 0 and var holding && Level == RunLevel.PedalDown)
        {
            // The modules' first watchdog stage: they heard nothing for modules.watchdog_ms and hold on their own,
            // refusing goals until acknowledged (at the next pedal down). The soft stage of module_fault.
            SoftTrip(SafetyCheck.ModuleFault, string.Empty, holding, 0, "modules holding", now);
        }

        if ((_robot.Faults & RobotFaults.SetpointRejected) != 0)
        {
            Trip(SafetyCheck.NonFinite, "setpoint", double.NaN, 0, "rad", now);
        }

        if (Level == RunLevel.PedalDown && StaleArm() is { } stale)
        {
            MasterTimeout(stale.Arm, stale.AgeMs, now);
        }

        CheckJumps(now);
        if (_graph.NewUpstreamFault() is { } fault)
        {
            Trip(SafetyCheck.PluginFault, fault.PlugIn, 0, 0, string.Empty, now, TripSource, fault.What);
        }

        // Driven: the motors are on and no trip has switched them off. Once one has, the goals no longer drive the
        // arms: a tracking error from then on (while the modules' torque-off is still being read back) is not a fault.
        _motorChecks.Check(driven: _robot.State == RobotState.Enabled && !_torqueOffTaken, homed: Level is RunLevel.PedalUp or RunLevel.PedalDown, now);
    }

    /// <summary>
    /// A host stall: the time since the last cycle (timed before each write and each check, while the motors hold or
    /// follow teleoperation; set-up and homing run the bus at their own pace, with the motors off or firmware-driven).
    /// </summary>
    private void CheckGap(long now)
    {
        var gap = _clock.Cycle(now, timed: Level is RunLevel.PedalUp or RunLevel.PedalDown);
        if (gap > _clock.StallTicks)
        {
            // What persisted across the stall was not observed beyond the stall limit: that part does not count. (A module's
            // silence does: a cycle slowed by a silent module's timeouts is a gap too, and the silence is real.)
            _motorChecks.Discount(gap - _clock.StallTicks);
            Trip(SafetyCheck.HostStall, string.Empty, _clock.Ms(gap), _clock.Ms(_clock.StallTicks), "ms", now);
        }
    }

    /// <summary>A jump at a master device (the loop's thread asked the robot to hold already): recorded, PEDAL_UP.</summary>
    private void CheckJumps(long now)
    {
        var jumps = _inputs.Jumps;
        if (jumps == _jumpsSeen)
        {
            return;
        }

        _jumpsSeen = jumps;
        var (arm, speed) = _inputs.LatestJump;
        Trip(SafetyCheck.MasterJump, _robot.Definition.Arms[arm].Name, speed, Limits.MasterSpeedMaxMmPerS, "mm/s", now);
    }

    /// <summary>The first arm whose input device data is older than the master timeout, with its age (ms), or null.</summary>
    private (int Arm, double AgeMs)? StaleArm()
    {
        for (var a = 0; a < _robot.ArmCount; a++)
        {
            var age = _inputs.AgeMs(a);
            if (!(age <= Limits.MasterTimeoutMs))
            {
                return (a, age);
            }
        }

        return null;
    }

    /// <summary>
    /// The master timeout: with the safe state hold, a soft trip (the arms hold, back to PEDAL_UP); with torque off, a
    /// trip like any other (E_STOP).
    /// </summary>
    private void MasterTimeout(int arm, double age, long now) =>
        Trip(SafetyCheck.MasterTimeout, _robot.Definition.Arms[arm].Name, age, Limits.MasterTimeoutMs, "ms", now);
}
