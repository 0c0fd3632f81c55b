using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The bus robot as one facade: what it accepts, the names it finds motors and modules by, set-up from another thread
/// run on the bus thread, the per-cycle check, a failed cycle, the full-state read it chooses and what it disposes.
/// </summary>
public sealed class BusRobotFacadeTests
{
    [Fact]
    public void A_robot_needs_a_file_with_modules_and_a_client()
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(ShippedRobots.Lb, clock);
        using var client = new BusClient(sim.OpenLink(), clock);
        Assert.Throws<ArgumentNullException>(() => new BusRobot(null!, client));
        Assert.Throws<ArgumentNullException>(() => new BusRobot(ShippedRobots.Lb, null!));

        var noModules = VirtualLb.EditedLb(json => json.AsObject().Remove("modules"));
        var refused = Assert.Throws<ArgumentException>(() => new BusRobot(noModules, client));
        Assert.StartsWith($"{noModules.SourceFile}: the robot file has no modules section; nothing to drive on the bus", refused.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Motors_and_modules_are_found_by_name_and_id()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        Assert.Equal("left.elbow", robot.Motor("left.elbow").Config.FullName);
        var missing = Assert.Throws<KeyNotFoundException>(() => robot.Motor("left.knee"));
        Assert.StartsWith("no motor 'left.knee' (motors: right.shoulder_yaw, ", missing.Message, StringComparison.Ordinal);
        Assert.Equal("left forearm", robot.Controller(13)!.Name);
        Assert.Null(robot.Controller(99));
    }

    [Fact]
    public void Every_cycle_runs_the_check_once_and_so_does_a_failed_one()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(5);
        Assert.Equal(5, rig.Checks);

        robot.CycleFailed(new IOException("link gone"), report: true, leftOut: 0);
        robot.CycleFailed(new IOException("link gone"), report: false, leftOut: 0);
        robot.CycleFailed(new IOException("link gone"), report: true, leftOut: 41);
        Assert.Equal(8, rig.Checks);
        Assert.Equal(["bus error: link gone", "bus error: link gone (41 more failed cycles since the last report)"], rig.Events<BusError>().Select(e => e.Message));
        Assert.True(robot.Faults.HasFlag(RobotFaults.BusDegraded));
        Assert.All(robot.Controllers, c => Assert.Equal(3, c.MissedReplies));
    }

    [Fact]
    public void The_cycle_reads_every_module_in_one_fast_bulk_read_when_all_firmware_answers_it()
    {
        using var rig = new TappedLb();
        rig.Tap.ClearSent();
        rig.Cycles(1);
        Assert.Equal([Instruction.SyncWrite, Instruction.FastBulkRead], rig.Tap.Sent.Select(f => f.Instruction));
    }

    [Fact]
    public void One_module_with_older_firmware_makes_the_cycle_read_with_sync_reads()
    {
        using var rig = new TappedLb(beforeStart: tap => tap.Rewrite = (request, reply) =>
            request?.Instruction == Instruction.Ping && reply.Id == 12 ? reply with { Parameters = [reply.Parameters[0], reply.Parameters[1], BusClient.FastReadFirmwareVersion - 1] } : null);
        var robot = rig.Robot;
        Assert.Equal(BusClient.FastReadFirmwareVersion - 1, robot.Controller(12)!.FirmwareVersion);
        rig.Tap.ClearSent();
        rig.Cycles(1);

        Assert.DoesNotContain(rig.Tap.Sent, f => f.Instruction == Instruction.FastBulkRead);
        Assert.Equal(3, rig.Tap.Sent.Count(f => f.Instruction == Instruction.SyncRead)); // one per feedback length: 3, 2 and 1 motors
        rig.Cycles(5);
        Assert.All(robot.Controllers, c => Assert.Equal((true, 0), (c.Present, c.MissedReplies)));
        Assert.InRange(robot.Motor("left.elbow").PositionRad - rig.Sim.Axis(1, "elbow").OutputAngleRad, -0.02, 0.02);
    }

    [Fact]
    public void A_robot_without_a_jaw_drive_has_no_jaw_goal_to_write()
    {
        var view = VirtualLb.EditedLb(json =>
        {
            var actuators = json["actuators"]!.AsArray();
            actuators.Remove(actuators.Single(a => (string)a!["name"]! == "tool_open_close"));
            foreach (var module in json["modules"]!["layout"]!.AsArray())
            {
                var motors = module!["motors"]!.AsArray();
                foreach (var jaw in motors.Where(m => (string)m!["actuator"]! == "tool_open_close").ToList())
                {
                    motors.Remove(jaw);
                }
            }
        });
        using var rig = new TappedLb(hostView: view);
        var robot = rig.Robot;
        Assert.Equal(10, robot.Motors.Count);
        rig.Cycles(3);
        var goals = robot.Motors.Select(robot.SentGoalRad).ToArray();

        robot.HoldPosition();
        robot.WriteJawSetpoint(0, robot.Map.JawMaxRad);
        robot.WriteJawSetpoint(1, robot.Map.JawMinRad);
        rig.Cycles(10);

        Assert.Equal(goals, robot.Motors.Select(robot.SentGoalRad));
    }

    [Fact]
    public void A_robot_file_that_lists_the_jaw_drive_first_still_drives_the_jaws()
    {
        var view = VirtualLb.EditedLb(json =>
        {
            var actuators = json["actuators"]!.AsArray();
            var jaw = actuators.Single(a => (string)a!["name"]! == "tool_open_close")!;
            actuators.Remove(jaw);
            actuators.Insert(0, jaw);
        });
        using var rig = new TappedLb(hostView: view);
        var robot = rig.Robot;
        var jaw = robot.Motor("right.tool_open_close");
        var target = jaw.PositionRad + (5 * Math.PI / 180);
        robot.WriteJawSetpoint(0, target);
        rig.Cycles(300);
        Assert.Equal(target, robot.SentGoalRad(jaw));
        Assert.InRange(jaw.PositionRad - target, -0.01, 0.01);
    }

    [Fact]
    public void Disposing_the_robot_stops_its_thread_and_closes_its_link()
    {
        var rig = new TappedLb();
        var robot = rig.Robot;
        robot.Start();
        Assert.True(robot.IsRunning);

        rig.Dispose();

        Assert.False(robot.IsRunning);
        Assert.True(rig.Tap.Disposed);
    }
}
