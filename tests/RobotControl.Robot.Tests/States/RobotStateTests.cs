using RobotControl.TestSupport;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Tests.States;

public sealed class RobotStateTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void The_bus_robot_moves_through_its_states_and_refuses_setup_out_of_order()
    {
        using var lb = new VirtualLb(start: false);
        Assert.Equal(RobotState.Disabled, lb.Robot.State);
        var error = Assert.Throws<InvalidOperationException>(() => lb.Robot.EnableTorque(true));
        Assert.Equal("turning the motors on needs the robot Discovered or Homed or Enabled, it is Disabled: discover the modules first, and clear faults if any", error.Message);
        Assert.Throws<InvalidOperationException>(() => lb.Robot.Home());
        Assert.Equal(RobotState.Disabled, lb.Robot.State);

        lb.Robot.Discover();
        lb.Robot.EnableTorque(true);
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.Throws<InvalidOperationException>(() => lb.Robot.Discover());
        Assert.Throws<InvalidOperationException>(() => lb.Robot.Home());

        lb.Robot.EnableTorque(false);
        Assert.Equal(RobotState.Discovered, lb.Robot.State);
        var homing = lb.Robot.Home();
        Assert.All(homing, r => Assert.True(r.Succeeded, r.ToString()));
        Assert.Equal(RobotState.Homed, lb.Robot.State);
        lb.Robot.EnableTorque(true);
        lb.Robot.EnableTorque(false);
        Assert.Equal(RobotState.Homed, lb.Robot.State); // motors off keeps the homing

        Assert.Equal(
            [
                (RobotState.Disabled, RobotState.Discovered),
                (RobotState.Discovered, RobotState.Enabled),
                (RobotState.Enabled, RobotState.Discovered),
                (RobotState.Discovered, RobotState.Homing),
                (RobotState.Homing, RobotState.Homed),
                (RobotState.Homed, RobotState.Enabled),
                (RobotState.Enabled, RobotState.Homed),
            ],
            lb.Robot.StateHistory.Select(t => (t.From, t.To)));
        Assert.Equal(["setup", "setup", "setup", "homing", "homing", "setup", "setup"], lb.Robot.StateHistory.Select(t => t.Source));
        Assert.All(lb.Robot.StateHistory, t => Assert.False(string.IsNullOrWhiteSpace(t.Reason)));
    }

    [Fact]
    public void A_tripped_watchdog_is_a_fault_state_until_faults_are_cleared()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [-40 * Deg, 0, 0, 120 * Deg, 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(100));
        lb.Sim.Advance(TimeSpan.FromMilliseconds(lb.Definition.Modules.WatchdogOffMs + 20)); // the host sends nothing, past stage 2
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        Assert.Equal(RobotState.Fault, lb.Robot.State);
        Assert.Contains("bus watchdog tripped", lb.Robot.StateHistory[^1].Reason, StringComparison.Ordinal);
        Assert.Equal("modules", lb.Robot.StateHistory[^1].Source);
        Assert.Throws<InvalidOperationException>(() => lb.Robot.EnableTorque(true));

        lb.Robot.ClearFaults();
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.Equal((RobotState.Fault, RobotState.Enabled, "faults cleared"), (lb.Robot.StateHistory[^1].From, lb.Robot.StateHistory[^1].To, lb.Robot.StateHistory[^1].Reason));
    }
}
