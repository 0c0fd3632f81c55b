using RobotControl.Robot.Bus;
using RobotControl.Robot.States;
using RobotControl.Simulation.Time;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The robot's states and what entering each does to torque and to the homing: motors off returns to homed only if the
/// robot was homed since it was last discovered; a fault keeps torque as it was, and clearing it returns there.
/// </summary>
public sealed class RobotLifecycleTests
{
    [Fact]
    public void Torque_is_on_in_enabled_kept_in_fault_and_off_in_every_other_state()
    {
        var life = new RobotLifecycle(new ManualTimeProvider());
        Assert.Equal(RobotState.Disabled, life.State);
        life.MotorsOff("test", "nothing discovered yet");
        life.EnterFault("no fault before discovery");
        Assert.Equal(RobotState.Disabled, life.State);
        Assert.Empty(life.Machine.History);

        life.Machine.MoveTo(RobotState.Discovered, "test", "discovered");
        Assert.False(life.TorqueEnabled);
        life.Machine.MoveTo(RobotState.Enabled, "test", "on");
        Assert.True(life.TorqueEnabled);
        life.EnterFault("a watchdog");
        Assert.Equal((RobotState.Fault, "modules", "a watchdog"), (life.State, life.Machine.History[^1].Source, life.Machine.History[^1].Reason));
        Assert.True(life.TorqueEnabled);
        life.EnterFault("a second fault"); // already there
        Assert.Equal("a watchdog", life.Machine.History[^1].Reason);
        life.LeaveFault("cleared");
        Assert.Equal((RobotState.Enabled, "modules", "cleared"), (life.State, life.Machine.History[^1].Source, life.Machine.History[^1].Reason));
        life.LeaveFault("not in a fault");
        Assert.Equal("cleared", life.Machine.History[^1].Reason);

        life.MotorsOff("test", "off");
        Assert.Equal(RobotState.Discovered, life.State);
        Assert.False(life.TorqueEnabled);
        life.EnterFault("while off");
        life.LeaveFault("cleared while off");
        Assert.Equal(RobotState.Discovered, life.State);
        Assert.False(life.TorqueEnabled);
    }

    [Fact]
    public void Motors_off_returns_to_homed_until_the_robot_is_discovered_again()
    {
        var life = new RobotLifecycle(new ManualTimeProvider());
        life.Machine.MoveTo(RobotState.Discovered, "test", "discovered");
        Assert.Equal(RobotState.Discovered, life.MotorsOffState);
        life.Machine.MoveTo(RobotState.Homing, "test", "homing");
        Assert.False(life.TorqueEnabled);
        life.Machine.MoveTo(RobotState.Homed, "test", "homed");
        Assert.Equal(RobotState.Homed, life.MotorsOffState);

        life.Machine.MoveTo(RobotState.Enabled, "test", "on");
        life.MotorsOff("test", "off");
        Assert.Equal(RobotState.Homed, life.State);
        Assert.False(life.TorqueEnabled);
        life.Machine.MoveTo(RobotState.Enabled, "test", "on");
        life.EnterFault("fault");
        life.MotorsOff("test", "off in a fault");
        Assert.Equal(RobotState.Homed, life.State);

        life.Machine.MoveTo(RobotState.Discovered, "test", "discovered again");
        Assert.Equal(RobotState.Discovered, life.MotorsOffState);
        life.Machine.MoveTo(RobotState.Enabled, "test", "on");
        life.EnterFault("fault");
        life.Machine.MoveTo(RobotState.Discovered, "test", "off");
        life.EnterFault("fault while off");
        life.LeaveFault("cleared");
        Assert.Equal(RobotState.Discovered, life.State);
    }
}
