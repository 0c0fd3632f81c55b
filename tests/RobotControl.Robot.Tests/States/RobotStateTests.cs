using RobotControl.TestSupport;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;
using RobotControl.Simulation.Time;

namespace RobotControl.Robot.Tests.States;

public sealed class RobotStateTests
{
    private const double Deg = Math.PI / 180;

    private static RobotStateMachine Machine(ManualTimeProvider clock, List<string> entered)
    {
        var m = new RobotStateMachine(clock);
        m.Declare(RobotState.Disabled, null, RobotState.Discovered);
        m.Declare(RobotState.Discovered, () => entered.Add("discovered"), RobotState.Homing, RobotState.Enabled);
        m.Declare(RobotState.Homing, () => entered.Add("homing"), RobotState.Homed, RobotState.Discovered);
        m.Declare(RobotState.Homed, () => entered.Add("homed"), RobotState.Enabled);
        m.Declare(RobotState.Enabled, () => entered.Add("enabled"), RobotState.Fault, RobotState.Homed);
        m.Declare(RobotState.Fault, () => entered.Add("fault"), RobotState.Enabled);
        return m;
    }

    [Fact]
    public void Every_move_runs_the_enter_action_and_is_recorded_with_time_and_reason()
    {
        var clock = new ManualTimeProvider();
        var entered = new List<string>();
        var m = Machine(clock, entered);
        m.MoveTo(RobotState.Discovered, "found 6 modules");
        clock.Advance(TimeSpan.FromMilliseconds(250));
        m.MoveTo(RobotState.Homing, "homing");
        m.MoveTo(RobotState.Homed, "all homed");
        m.MoveTo(RobotState.Enabled, "motors on");
        m.MoveTo(RobotState.Enabled, "motors on again"); // staying is no move

        Assert.Equal(RobotState.Enabled, m.Current);
        Assert.Equal(["discovered", "homing", "homed", "enabled"], entered);
        var history = m.History;
        Assert.Equal(4, history.Count);
        Assert.Equal(new RobotTransition(TimeSpan.Zero, RobotState.Disabled, RobotState.Discovered, "found 6 modules"), history[0]);
        Assert.Equal(TimeSpan.FromMilliseconds(250), history[1].At);
        Assert.Equal((RobotState.Homing, RobotState.Homed, "all homed"), (history[2].From, history[2].To, history[2].Reason));
    }

    [Fact]
    public void A_move_the_declaration_does_not_allow_is_refused_and_changes_nothing()
    {
        var entered = new List<string>();
        var m = Machine(new ManualTimeProvider(), entered);
        var error = Assert.Throws<InvalidOperationException>(() => m.MoveTo(RobotState.Enabled, "motors on"));
        Assert.Contains("from Disabled to Enabled", error.Message, StringComparison.Ordinal);
        Assert.Contains("may go to Discovered", error.Message, StringComparison.Ordinal);
        Assert.Equal(RobotState.Disabled, m.Current);
        Assert.Empty(m.History);
        Assert.Empty(entered);
        Assert.False(m.CanMoveTo(RobotState.Homed));

        m.MoveTo(RobotState.Discovered, "found");
        Assert.Throws<InvalidOperationException>(() => m.MoveTo(RobotState.Fault, "no path from Discovered in this declaration"));
        Assert.Equal(RobotState.Discovered, m.Current);
    }

    [Fact]
    public void A_state_is_declared_once_and_preconditions_name_the_action_and_the_state()
    {
        var m = Machine(new ManualTimeProvider(), []);
        Assert.Throws<InvalidOperationException>(() => m.Declare(RobotState.Homed, null, RobotState.Discovered));
        var error = Assert.Throws<InvalidOperationException>(() => m.Require("homing", "discover first", RobotState.Discovered, RobotState.Homed));
        Assert.Equal("homing needs the robot Discovered or Homed, it is Disabled: discover first", error.Message);
        Assert.Throws<ArgumentException>(() => m.MoveTo(RobotState.Discovered, " "));
    }

    [Fact]
    public void The_bus_robot_moves_through_its_states_and_refuses_setup_out_of_order()
    {
        using var lb = new VirtualLb(start: false);
        Assert.Equal(RobotState.Disabled, lb.Robot.State);
        var error = Assert.Throws<InvalidOperationException>(() => lb.Robot.EnableTorque(true));
        Assert.Contains("turning the motors on needs the robot", error.Message, StringComparison.Ordinal);
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
        Assert.All(lb.Robot.StateHistory, t => Assert.False(string.IsNullOrWhiteSpace(t.Reason)));
    }

    [Fact]
    public void A_tripped_watchdog_is_a_fault_state_until_faults_are_cleared()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [-40 * Deg, 0, 0, 120 * Deg, 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(100));
        lb.Sim.Advance(TimeSpan.FromMilliseconds(lb.Definition.Modules.WatchdogMs + 20)); // the host sends nothing
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        Assert.Equal(RobotState.Fault, lb.Robot.State);
        Assert.Contains("bus watchdog tripped", lb.Robot.StateHistory[^1].Reason, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => lb.Robot.EnableTorque(true));

        lb.Robot.ClearFaults();
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(30));
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.Equal((RobotState.Fault, RobotState.Enabled, "faults cleared"), (lb.Robot.StateHistory[^1].From, lb.Robot.StateHistory[^1].To, lb.Robot.StateHistory[^1].Reason));
    }
}
