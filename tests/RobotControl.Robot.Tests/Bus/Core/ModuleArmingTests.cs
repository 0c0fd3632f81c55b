using RobotControl.Bus.Protocol;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// Switching modules on and off: torque, then the bus watchdog (the robot file's period when on, 0 when off); a module
/// that refuses is an <see cref="IOException"/> naming it, and turning off tells every module even when one refuses.
/// </summary>
public sealed class ModuleArmingTests
{
    [Fact]
    public void On_arms_each_watchdog_with_the_files_period_and_off_disarms_it()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var period = rig.Lb.Definition.Modules.WatchdogMs;
        Assert.All(robot.Controllers, c => Assert.Equal((1, period), (robot.ReadParameter(c.Id, "torque_enable", c.Motors.Count - 1), robot.ReadParameter(c.Id, "bus_watchdog"))));
        Assert.All(robot.Controllers, c => Assert.Equal(-1, c.BusWatchdogMs)); // unknown until the status poll reads it back
        rig.Cycles(8);
        Assert.All(robot.Controllers, c => Assert.Equal(period, c.BusWatchdogMs));

        robot.EnableTorque(false);
        Assert.All(robot.Controllers, c => Assert.Equal((0, 0), (robot.ReadParameter(c.Id, "torque_enable", c.Motors.Count - 1), robot.ReadParameter(c.Id, "bus_watchdog"))));
        Assert.All(robot.Controllers, c => Assert.Equal(-1, c.BusWatchdogMs));
        rig.Cycles(8);
        Assert.All(robot.Controllers, c => Assert.Equal(0, c.BusWatchdogMs));
    }

    [Fact]
    public void A_module_with_its_watchdog_error_latched_refuses_the_motors_on()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(3);
        rig.SilenceBeyondTheWatchdog();

        var refused = Assert.Throws<IOException>(() => robot.EnableTorque(true));
        Assert.Contains("module 1 \"right shoulder\"", refused.Message, StringComparison.Ordinal);
        Assert.Contains("watchdog error is latched", refused.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Turning_off_tells_every_module_and_throws_the_first_refusal_after_the_state_moved()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(3);

        var torque = ControlTable.Firmware["torque_enable"].At(0);
        rig.Tap.Rewrite = (request, reply) => request is { } r && r.IsWrite(r.Id, torque) && r.Id is 3 or 12 ? reply with { Error = 0x07 } : null;
        var refused = Assert.Throws<IOException>(() => robot.EnableTorque(false));

        Assert.Contains("module 3 \"right forearm\"", refused.Message, StringComparison.Ordinal);
        Assert.Equal(["module 3", "module 12"], rig.Events<TorqueRefused>().Select(e => e.Message[..(e.Message.IndexOf(' ', 7))]));
        Assert.Equal(RobotState.Discovered, robot.State);
        rig.Sim.Advance(TimeSpan.FromMilliseconds(1));
        Assert.All(rig.Sim.Axes, a => Assert.False(a.DriverEnabled)); // told, whatever they answered
    }
}
