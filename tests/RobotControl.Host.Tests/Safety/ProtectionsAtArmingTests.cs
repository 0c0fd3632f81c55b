using RobotControl.Host.Safety;
using RobotControl.Robot.States;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// Issue 29: the safety supervisor does not arm a module that has a protection switched off (a current limit or a
/// speed limit of 0 in its FRAM, written on purpose with <c>params set --allow-protection-off</c> or by another tool):
/// homing is refused with one line naming the module, the motor, the field and the value, nothing moves, and with the
/// value restored it arms as usual.
/// </summary>
public sealed class ProtectionsAtArmingTests
{
    [Theory]
    [InlineData("current_limit", "the motor's current limit")]
    [InlineData("speed_limit", "the motor's setpoint speed limit")]
    public void A_module_with_a_protection_off_is_not_armed_and_the_refusal_names_module_field_and_value(string field, string protection)
    {
        using var lb = new SupervisedLb(home: false);
        var (elbow, _) = lb.Motor("right.elbow");
        var module = lb.Robot.Controllers.Single(c => c.Motors.Contains(elbow));
        var channel = elbow.Config.Channel;
        var kept = lb.Robot.ReadParameter(module.Id, field, channel);
        lb.Robot.WriteParameter(module.Id, field, channel, 0, allowProtectionOff: true);

        var refused = Assert.Throws<InvalidOperationException>(() => lb.Supervisor.Home("console"));

        Assert.Equal(
            $"homing (console) refused: module {module.Id} \"{module.Name}\", motor right.elbow (channel {channel}): {field}[{channel}] is 0: {field} = 0 switches {protection} off; the supervisor does not arm a module without its protections (write the robot file's values: robotctl params set --from-robot-file)",
            refused.Message);
        Assert.Equal((RunLevel.Init, RobotState.Discovered), (lb.Supervisor.Level, lb.Robot.State));
        Assert.Empty(lb.Supervisor.History);

        lb.Robot.WriteParameter(module.Id, field, channel, kept);
        lb.Supervisor.Home("console");
        Assert.Equal((RunLevel.PedalUp, RobotState.Enabled), (lb.Supervisor.Level, lb.Robot.State));
    }

    [Fact]
    public void A_protection_off_on_a_channel_the_robot_file_does_not_drive_does_not_stop_arming()
    {
        using var lb = new SupervisedLb(home: false);
        var module = lb.Robot.Controllers.First(c => c.Motors.Count < 4);
        var unused = Enumerable.Range(0, 4).First(ch => !Drives(module, ch));
        lb.Robot.WriteParameter(module.Id, "current_limit", unused, 0, allowProtectionOff: true);

        lb.Supervisor.Home("console");

        Assert.Equal(RunLevel.PedalUp, lb.Supervisor.Level);
    }

    private static bool Drives(RobotControl.Robot.Bus.RobotController module, int channel) => module.Motors.Any(m => m.Config.Channel == channel);
}
