using RobotControl.Robot.Control.States;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The robot's life (a <see cref="StateMachine{TState}"/> of <see cref="RobotState"/>), its states each declared once
/// with what entering them does: <see cref="RobotState.Disabled"/> -> <see cref="RobotState.Discovered"/> ->
/// <see cref="RobotState.Homing"/> -> <see cref="RobotState.Homed"/> -> <see cref="RobotState.Enabled"/>, and
/// <see cref="RobotState.Fault"/> when a module stops its motors. Torque is on in <see cref="RobotState.Enabled"/> and
/// stays as it was in <see cref="RobotState.Fault"/> (the modules stopped their motors; clearing the faults re-arms
/// them). Moved by the bus thread alone (set-up runs between cycles, supervision in the cycle).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class RobotLifecycle
{
    /// <summary>The source of the moves module supervision makes (faults and their clearing).</summary>
    private const string ModulesSource = "modules";
    private volatile bool _torqueEnabled;
    private volatile bool _homed;

    public RobotLifecycle(TimeProvider time)
    {
        Machine = new StateMachine<RobotState>("the robot", time, RobotState.Disabled);
        Machine.Declare(RobotState.Disabled, null, RobotState.Discovered);
        Machine.Declare(RobotState.Discovered, () => (_torqueEnabled, _homed) = (false, false), RobotState.Homing, RobotState.Enabled, RobotState.Fault);
        Machine.Declare(RobotState.Homing, () => _torqueEnabled = false, RobotState.Homed, RobotState.Discovered);
        Machine.Declare(RobotState.Homed, () => (_torqueEnabled, _homed) = (false, true), RobotState.Discovered, RobotState.Homing, RobotState.Enabled, RobotState.Fault);
        Machine.Declare(RobotState.Enabled, () => _torqueEnabled = true, RobotState.Discovered, RobotState.Homed, RobotState.Fault);
        Machine.Declare(RobotState.Fault, null, RobotState.Enabled, RobotState.Discovered, RobotState.Homed);
    }

    public StateMachine<RobotState> Machine { get; }

    public RobotState State => Machine.Current;

    /// <summary>True while the motors are driven (or were, when a fault came).</summary>
    public bool TorqueEnabled => _torqueEnabled;

    /// <summary>The state motors-off leads to: homed if the robot was homed since it was last discovered.</summary>
    public RobotState MotorsOffState => _homed ? RobotState.Homed : RobotState.Discovered;

    /// <summary>Motors off: to <see cref="MotorsOffState"/> unless the robot was never discovered.</summary>
    public void MotorsOff(string source, string reason)
    {
        if (Machine.Current != RobotState.Disabled)
        {
            Machine.MoveTo(MotorsOffState, source, reason);
        }
    }

    /// <summary>A module stopped its motors or latched an error: <see cref="RobotState.Fault"/> until faults are cleared or the motors turned off.</summary>
    public void EnterFault(string reason)
    {
        if (Machine.CanMoveTo(RobotState.Fault))
        {
            Machine.MoveTo(RobotState.Fault, ModulesSource, reason);
        }
    }

    /// <summary>Faults cleared: from <see cref="RobotState.Fault"/> back to <see cref="RobotState.Enabled"/> if the motors were on, else to <see cref="MotorsOffState"/>.</summary>
    public void LeaveFault(string reason)
    {
        if (Machine.Current == RobotState.Fault)
        {
            Machine.MoveTo(_torqueEnabled ? RobotState.Enabled : MotorsOffState, ModulesSource, reason);
        }
    }
}
