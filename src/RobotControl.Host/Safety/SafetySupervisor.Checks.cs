using System.Globalization;
using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Host.Safety;

/// <summary>The per-cycle checks, run inside the bus cycle between read and write; allocation-free while nothing trips.</summary>
public sealed partial class SafetySupervisor
{
    /// <summary>The per-cycle checks: step <b>check</b> of the robot's cycle, on the bus thread.</summary>
    void ICycleCheck.Check()
    {
        FollowOperator();
        if (Level == RunLevel.Init)
        {
            _lastCycle = 0;
            return; // motors off and nothing commanded: the checks start with homing
        }

        var now = _time.GetTimestamp();
        var gap = _lastCycle == 0 ? 0 : now - _lastCycle;
        // Cycles are timed only while the motors hold or follow teleoperation (PEDAL_UP, PEDAL_DOWN): set-up and
        // homing run the bus at their own pace (first calls, homing moves), with the motors off or firmware-driven.
        _lastCycle = Level is RunLevel.PedalUp or RunLevel.PedalDown ? now : 0;
        if (gap > _stallTicks)
        {
            Trip(SafetyCheck.DeadlineMiss, string.Empty, Ms(gap), Ms(_stallTicks), "ms", now);
        }

        _moduleChecks.CheckSilence(now);
        if (_robot.State == RobotState.Enabled && Level is RunLevel.PedalUp or RunLevel.PedalDown)
        {
            _moduleChecks.CheckWatchdogs(now);
        }
        if (_robot.State == RobotState.Fault)
        {
            Trip(SafetyCheck.ModuleFault, string.Empty, (double)_robot.Faults, 0, "fault flags", now);
        }

        if ((_robot.Faults & RobotFaults.SetpointRejected) != 0)
        {
            Trip(SafetyCheck.NonFinite, "setpoint", double.NaN, 0, "rad", now);
        }

        if (Level == RunLevel.PedalDown && StaleArm() is { } stale)
        {
            MasterTimeout(stale.Arm, stale.AgeMs, now);
        }

        _motorChecks.Check(driven: _robot.State == RobotState.Enabled, homed: Level is RunLevel.PedalUp or RunLevel.PedalDown, now);
    }

    /// <summary>The first arm whose input device data is older than the master timeout, with its age (ms), or null.</summary>
    private (int Arm, double AgeMs)? StaleArm()
    {
        for (var a = 0; a < _arms; a++)
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
    /// The master timeout: with the safe state hold, the trip is recorded and the run level goes back to PEDAL_UP (the
    /// arms hold, teleoperation is ignored); with torque off, it is a trip like any other (E_STOP).
    /// </summary>
    private void MasterTimeout(int arm, double age, long now)
    {
        var joint = _robot.Definition.Arms[arm].Name;
        if (_safeStates[(int)SafetyCheck.MasterTimeout] == SafeState.TorqueOff)
        {
            Trip(SafetyCheck.MasterTimeout, joint, age, Limits.MasterTimeoutMs, "ms", now);
            return;
        }

        lock (_tripGate)
        {
            if (!_tripped[(int)SafetyCheck.MasterTimeout])
            {
                _tripped[(int)SafetyCheck.MasterTimeout] = true;
                _trips.Add(new SafetyTrip(now, SafetyCheck.MasterTimeout, joint, age, Limits.MasterTimeoutMs, "ms", SafeState.Hold));
            }
        }

        PedalUpOnBus(TripSource, string.Create(CultureInfo.InvariantCulture, $"master_timeout {joint}: input data {age:0.#} ms old (limit {Limits.MasterTimeoutMs:0.#}): hold"));
    }

}
