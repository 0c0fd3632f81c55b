using RobotControl.Bus.Protocol;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// Set-up on the bus: discovery (a broadcast ping, a ping of its own for a module whose answer was lost, modules that
/// are not what the file says), parameters read back, reboots, each refused in the states it does not fit.
/// </summary>
public sealed class RobotSetupTests
{
    [Fact]
    public void Discovery_pings_a_module_on_its_own_only_when_its_answer_to_the_broadcast_was_lost()
    {
        using var rig = new TappedLb(start: false);
        var lost = false;
        rig.Tap.LoseReply = (request, id) =>
        {
            if (request?.Id == FrameConstants.BroadcastId && request.Instruction == Instruction.Ping && id == 2 && !lost)
            {
                lost = true;
                return true;
            }

            return false;
        };

        var report = rig.Robot.Discover();

        Assert.True(report.AllAsConfigured, string.Join("\n", report.Lines()));
        Assert.Equal([(FrameConstants.BroadcastId, Instruction.Ping), (2, Instruction.Ping)], rig.Tap.Sent.Where(f => f.Instruction == Instruction.Ping).Select(f => (f.Id, f.Instruction)));
        Assert.Equal(RobotState.Discovered, rig.Robot.State);
        Assert.Equal(("setup", "discovery: 6 of 6 modules as configured"), (rig.Robot.StateHistory[^1].Source, rig.Robot.StateHistory[^1].Reason));
    }

    [Fact]
    public void A_module_gone_at_a_second_discovery_no_longer_takes_part()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        robot.EnableTorque(false);
        rig.Tap.Mute(2);

        var report = robot.Discover();

        Assert.Equal([2], report.Missing.Select(c => (int)c.Id));
        Assert.False(robot.Controller(2)!.Present);
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        rig.Tap.ClearSent();
        rig.Cycles(2);
        Assert.DoesNotContain(rig.Tap.Sent, f => f.Instruction == Instruction.FastBulkRead && f.Parameters.Where((_, i) => i % 5 == 0).Contains((byte)2));
    }

    [Fact]
    public void A_module_of_another_model_is_a_mismatch_not_a_missing_module()
    {
        using var rig = new TappedLb(start: false);
        rig.Tap.Rewrite = (request, reply) => request?.Instruction == Instruction.Ping && reply.Id == 3
            ? reply with { Parameters = [0xD2, 0x04, reply.Parameters[2]] } // model 1234
            : null;

        var report = rig.Robot.Discover();

        Assert.Equal(["id 3 \"right forearm\": model number 1234, expected 19761 (not a RobotControl motor module)"], report.Mismatched);
        Assert.Empty(report.Missing);
        Assert.DoesNotContain(report.Present, c => c.Id == 3);
        Assert.Equal(5, report.Present.Count);
        Assert.False(rig.Robot.Controller(3)!.Present);
        Assert.Equal(1234, rig.Robot.Controller(3)!.ModelNumber);
        Assert.True(rig.Robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        Assert.Contains(rig.Events<DiscoveryProblemEvent>(), e => e.Problem.Kind == DiscoveryProblemKind.Mismatched);
    }

    [Fact]
    public void A_module_that_drives_fewer_motors_than_the_file_uses_is_a_mismatch()
    {
        // The host's file puts the right jaw on channel 2 of the right forearm, which drives two motors.
        var view = VirtualLb.EditedLb(json =>
        {
            var forearm = json["modules"]!["layout"]!.AsArray().Single(m => (int)m!["id"]! == 3)!;
            forearm["motors"]!.AsArray()[1]!["channel"] = 2;
        });
        using var rig = new TappedLb(start: false, hostView: view);

        var report = rig.Robot.Discover();

        Assert.Equal(["id 3 \"right forearm\": drives 2 motors, the robot file uses channels up to 2"], report.Mismatched);
        Assert.Empty(report.Missing);
        Assert.Equal(5, report.Present.Count);
        Assert.True(report.Present.All(c => c.Id != 3));
    }

    [Fact]
    public void Discovery_is_refused_while_the_motors_are_on()
    {
        using var rig = new TappedLb();
        var refused = Assert.Throws<InvalidOperationException>(() => rig.Robot.Discover());
        Assert.Equal("discovery needs the robot Disabled or Discovered or Homed, it is Enabled: turn the motors off first (EnableTorque(false))", refused.Message);
    }

    [Fact]
    public void Checking_parameters_names_a_module_that_does_not_answer()
    {
        using var rig = new TappedLb();
        rig.Robot.EnableTorque(false);
        rig.Tap.Mute(12);
        var failed = Assert.Throws<IOException>(() => rig.Robot.CheckParameters());
        Assert.StartsWith("module 12 \"left upper arm\": reading its parameters failed (Timeout", failed.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Reboot_restarts_a_module_with_the_motors_off_and_is_refused_while_they_are_on()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var refused = Assert.Throws<InvalidOperationException>(() => robot.Reboot(2));
        Assert.Equal("rebooting module 2 needs the robot Disabled or Discovered or Homed, it is Enabled: turn the motors off first", refused.Message);

        robot.EnableTorque(false);
        Assert.True(robot.Reboot(2).Succeeded);
        robot.RunFor(TimeSpan.FromMilliseconds(50));
        var reset = Assert.Single(rig.Events<ModuleResetEvent>());
        Assert.Equal((byte)2, reset.ModuleId);
        Assert.Equal(1, robot.Controller(2)!.Resets);
    }
}
