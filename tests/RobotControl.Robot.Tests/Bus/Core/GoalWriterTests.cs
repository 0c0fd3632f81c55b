using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The cycle's write step: the step cap (speed limit times the time since the last write, on the bus clock), the
/// hold at the measured positions, the motors off (goals on the positions), and the requests other threads make.
/// </summary>
public sealed class GoalWriterTests
{
    private const double Deg = Math.PI / 180;
    private static readonly int GoalAddress = ControlTable.Firmware["goal_position"].At(0);

    private static List<long> GoalWrites(TappedLb rig) =>
        [.. rig.Tap.Sent.Where(f => f.Instruction == Instruction.SyncWrite && f.Address == GoalAddress).Select(f => f.Timestamp)];

    [Fact]
    public void A_far_goal_moves_by_the_speed_limit_times_the_time_since_the_last_write_and_stops_on_the_target()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var elbow = robot.Motor("right.elbow");
        rig.Cycles(3);
        var hitsBefore = robot.StepCapHits;
        Assert.Equal(0, robot.LargestCappedStepRad);
        var from = robot.SentGoalRad(elbow);
        var target = from + (20 * Deg); // the elbow's 90 deg/s covers it in about 0.22 s
        var earlier = GoalWrites(rig).Count;

        elbow.SetSetpoint(target);
        var sent = new List<double>();
        while (sent.Count < 400 && (sent.Count == 0 || sent[^1] != target))
        {
            robot.RunCycle();
            sent.Add(robot.SentGoalRad(elbow));
        }

        // The time of each write is when its goals went on the wire (nothing moves the bus clock within a write).
        var writes = GoalWrites(rig);
        Assert.Equal(earlier + sent.Count, writes.Count);
        var previous = from;
        for (var i = 0; i < sent.Count; i++)
        {
            var dt = (writes[earlier + i] - writes[earlier + i - 1]) / (double)rig.Clock.TimestampFrequency;
            var cap = BusRobot.StepCapRad(elbow, dt);
            Assert.True(dt > 0);
            if (i < sent.Count - 1)
            {
                Assert.Equal(previous + cap, sent[i], 12);
            }
            else
            {
                Assert.True(sent[i] - previous <= cap + 1e-9, $"the last step: {sent[i] - previous} rad, cap {cap}");
            }

            previous = sent[i];
        }

        Assert.InRange(sent.Count, 10, 399);
        Assert.Equal(target, sent[^1]);
        Assert.Equal(hitsBefore + sent.Count - 1, robot.StepCapHits); // every write but the last was shortened, only the elbow's
        Assert.Equal(target - from, robot.LargestCappedStepRad, 12); // the first write was asked for the whole move

        // A smaller capped step later does not lower the largest one.
        elbow.SetSetpoint(target - (5 * Deg));
        robot.RunCycle();
        Assert.Equal(hitsBefore + sent.Count, robot.StepCapHits);
        Assert.Equal(target - from, robot.LargestCappedStepRad, 12);
    }

    [Fact]
    public void The_step_cap_is_the_speed_limit_times_the_time()
    {
        using var rig = new TappedLb(start: false);
        var elbow = rig.Robot.Motor("right.elbow");
        Assert.Equal(90 * Deg * 0.25, BusRobot.StepCapRad(elbow, 0.25), 12);
        Assert.Throws<ArgumentNullException>(() => BusRobot.StepCapRad(null!, 1));
        Assert.Throws<ArgumentNullException>(() => rig.Robot.SentGoalRad(null!));
    }

    [Fact]
    public void The_goals_on_the_wire_are_the_sent_goals_in_counts_for_every_module()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        robot.Motor("right.shoulder_pitch").SetSetpoint(robot.Motor("right.shoulder_pitch").PositionRad + (2 * Deg));
        robot.Motor("left.tool_open_close").SetSetpoint(robot.Motor("left.tool_open_close").PositionRad - (2 * Deg));
        rig.Cycles(5);
        rig.Tap.ClearSent();
        robot.RunCycle();

        var write = Assert.Single(rig.Tap.Sent, f => f.Instruction == Instruction.SyncWrite);
        var p = write.Parameters;
        Assert.Equal(GoalAddress, BinaryPrimitives.ReadUInt16LittleEndian(p));
        var length = BinaryPrimitives.ReadUInt16LittleEndian(p.AsSpan(2));
        Assert.Equal(12, length); // three channels of four bytes: the widest module's goals
        Assert.Equal(4 + (robot.Controllers.Count * (1 + length)), p.Length);
        for (var i = 0; i < robot.Controllers.Count; i++)
        {
            var block = p.AsSpan(4 + (i * (1 + length)), 1 + length);
            var c = robot.Controller(block[0])!;
            foreach (var m in c.Motors)
            {
                Assert.Equal(m.Config.ToCounts(robot.SentGoalRad(m)), BinaryPrimitives.ReadInt32LittleEndian(block[(1 + (4 * m.Config.Channel))..]));
            }
        }

        Assert.Equal([1, 2, 3, 11, 12, 13], p.Where((_, i) => i >= 4 && (i - 4) % (1 + length) == 0).Select(b => (int)b));
    }

    [Fact]
    public void Before_discovery_the_steps_of_a_cycle_send_and_publish_nothing()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        robot.Write();
        robot.Read();
        for (var i = 0; i < 16; i++)
        {
            robot.Publish(); // cycles 8 and 16 would poll the status, cycle 8 the pots
        }

        Assert.Empty(rig.Tap.Sent);
        Assert.Equal(RobotFaults.None, robot.Faults);
        Assert.Equal(16, robot.Cycles);
    }

    [Fact]
    public void Before_the_first_write_the_sent_goal_is_the_measured_position()
    {
        using var rig = new TappedLb(); // discovered, motors on: the positions are read, nothing written yet
        var robot = rig.Robot;
        var elbow = robot.Motor("right.elbow");
        Assert.NotEqual(0, elbow.PositionRad);
        Assert.Equal(elbow.PositionRad, robot.SentGoalRad(elbow));
    }

    [Fact]
    public void A_hold_freezes_the_goals_at_the_measured_positions_until_released()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(10);

        robot.HoldAtMeasured();
        Assert.True(robot.IsHolding);
        var measured = robot.Motors.Select(m => Math.Clamp(m.PositionRad, m.Config.OutputMinRad, m.Config.OutputMaxRad)).ToArray();
        robot.RunCycle(); // the write takes the positions the last cycle published
        Assert.Equal(measured, robot.Motors.Select(robot.SentGoalRad));

        var min = robot.Definition.Joints.Select(j => j.MinRad).ToArray();
        robot.WriteJointSetpoints(0, min);
        robot.WriteJointSetpoints(1, min);
        rig.Cycles(30);
        Assert.Equal(measured, robot.Motors.Select(robot.SentGoalRad));

        robot.ReleaseHold();
        Assert.False(robot.IsHolding);
        rig.Cycles(3);
        Assert.True(robot.SentGoalRad(robot.Motors[0]) < measured[0], "released: the goals follow the setpoints again");
    }

    [Fact]
    public void With_the_motors_off_the_goals_follow_the_positions_however_far_they_jump()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var elbowAxis = rig.Sim.Axis(0, "elbow");
        var elbow = robot.Motor("right.elbow");
        robot.WriteJointSetpoints(0, robot.Definition.Joints.Select(j => j.MidRad + (0.2 * (j.MaxRad - j.MidRad))).ToArray());
        rig.Cycles(30);

        // Motors off: at the next write every goal is its motor's position (not the setpoint the motors were driving to).
        robot.EnableTorque(false);
        var positions = robot.Motors.Select(m => m.PositionRad).ToArray();
        robot.RunCycle();
        for (var i = 0; i < robot.Motors.Count; i++)
        {
            Assert.Equal(positions[i], robot.SentGoalRad(robot.Motors[i]));
        }

        // Homing moves a position by far more than one write's step cap: the goal follows at once.
        rig.Sim.TurnWhileOff(elbowAxis, elbowAxis.OutputAngleRad + (30 * Deg));
        rig.Sim.Advance(TimeSpan.FromMilliseconds(2));
        Assert.All(robot.Home(), r => Assert.True(r.Succeeded, r.ToString()));
        Assert.Equal(RobotState.Homed, robot.State);
        var homed = elbow.PositionRad;
        Assert.InRange(homed - elbowAxis.OutputAngleRad, -0.5 * Deg, 0.5 * Deg);
        robot.RunCycle();
        Assert.Equal(homed, robot.SentGoalRad(elbow));
    }

    [Fact]
    public void A_jog_started_before_the_first_write_starts_from_the_position()
    {
        using var rig = new TappedLb(); // discovered, motors on, nothing written yet
        var robot = rig.Robot;
        var roll = robot.Motor("right.tool_roll");
        var at = roll.PositionRad;
        roll.Jog(0.5);
        robot.RunCycle(); // no time has passed since a write: the jog has not moved the goal yet
        Assert.Equal(at, robot.SentGoalRad(roll));
        robot.RunCycle();
        Assert.True(robot.SentGoalRad(roll) > at);
    }

    [Fact]
    public void A_manual_setpoint_drives_its_motor_while_the_others_hold_and_turning_on_releases_it()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var pitch = robot.Motor("left.shoulder_pitch");
        var goal = pitch.PositionRad + (3 * Deg);
        pitch.SetSetpoint(goal);
        rig.Cycles(150);
        Assert.Equal(goal, robot.SentGoalRad(pitch));
        Assert.InRange(pitch.PositionRad - goal, -0.5 * Deg, 0.5 * Deg);

        robot.EnableTorque(false);
        robot.EnableTorque(true);
        Assert.False(pitch.IsManual);
    }

    [Fact]
    public void An_emergency_hold_holds_at_the_next_write_and_with_torque_off_turns_the_motors_off()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(3);

        robot.EmergencyHold("first stop", torqueOff: false);
        Assert.True(robot.StopPending);
        rig.Cycles(2);
        Assert.False(robot.StopPending);
        Assert.True(robot.IsHolding);
        Assert.Equal(RobotState.Enabled, robot.State);
        Assert.All(rig.Sim.Axes, a => Assert.True(a.DriverEnabled));

        robot.ReleaseHold();
        robot.EmergencyHold("test stop", torqueOff: true);
        Assert.Equal(RobotState.Enabled, robot.State); // requests are taken at the next write
        robot.Write();

        Assert.False(robot.StopPending);
        Assert.True(robot.IsHolding);
        Assert.Equal(RobotState.Discovered, robot.State);
        var last = robot.StateHistory[^1];
        Assert.Equal(("emergency hold", "test stop"), (last.Source, last.Reason));
        rig.Sim.Advance(TimeSpan.FromMilliseconds(1));
        Assert.All(rig.Sim.Axes, a => Assert.False(a.DriverEnabled, $"{a.Config.FullName} still driven"));
        Assert.All(robot.Controllers, c => Assert.Equal(0, robot.ReadParameter(c.Id, "bus_watchdog")));
    }

    [Fact]
    public void A_requested_torque_off_before_discovery_or_after_the_motors_are_off_changes_nothing()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        robot.RequestTorqueOff("nothing to stop");
        robot.Write();
        Assert.Equal(RobotState.Disabled, robot.State);
        Assert.Empty(robot.StateHistory);
        Assert.Empty(rig.Tap.Sent);

        robot.Discover();
        robot.EnableTorque(true);
        robot.RequestTorqueOff("supervisor says so");
        rig.Cycles(1);
        Assert.Equal(RobotState.Discovered, robot.State);
        Assert.Equal("supervisor says so", robot.StateHistory[^1].Reason);
    }

    [Fact]
    public void A_clear_is_taken_once_and_faults_latched_after_it_stay_latched()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var statusAddress = ControlTable.Firmware["hardware_error_status"].At(0);
        rig.Cycles(3);
        rig.Tap.ClearSent();

        robot.ClearFaults();
        rig.Cycles(3);
        Assert.Equal(robot.Controllers.Select(c => (int)c.Id), rig.Tap.Sent.Where(f => f.Instruction == Instruction.Write && f.Address == statusAddress && f.Parameters.Length == 4).Select(f => (int)f.Id));

        rig.Sim.ScheduleReset(2, rig.Sim.Elapsed + TimeSpan.FromMilliseconds(1));
        robot.RunFor(TimeSpan.FromMilliseconds(100));
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleReset));
        rig.Cycles(20);
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleReset), "latched until the next clear");
        robot.ClearFaults();
        rig.Cycles(1);
        Assert.False(robot.Faults.HasFlag(RobotFaults.ModuleReset));
    }

    [Fact]
    public void A_manual_motor_follows_its_manual_goal_while_its_loop_goal_stays_the_setpoint_that_release_hands_it_back_to()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var elbow = robot.Motor("right.elbow");
        rig.Cycles(3);
        var q = new double[robot.Definition.JointCount];
        robot.ReadJointPositions(0, q);
        var manual = elbow.PositionRad;
        elbow.SetSetpoint(manual);
        q[3] += 30 * Deg; // the elbow joint drives the elbow motor alone (coupling 1)
        robot.WriteJointSetpoints(0, q);
        rig.Cycles(50);

        Assert.Equal(q[3], robot.LoopGoalRad(elbow), 9);
        Assert.Equal(manual, robot.SentGoalRad(elbow), 9);

        elbow.ReleaseManual();
        rig.Cycles(1);
        Assert.True(robot.SentGoalRad(elbow) > manual, $"after release the goal sent moves toward the loop's: {robot.SentGoalRad(elbow)} rad, manual {manual} rad");
        Assert.Equal(q[3], robot.LoopGoalRad(elbow), 9);
    }
}
