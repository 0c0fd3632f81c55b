using RobotControl.Bus.Protocol;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.States;
using RobotControl.Robot.Events;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The feedback's read and publish steps: each motor's position and current, the arms' joints and currents, modules
/// that stop answering (after <see cref="BusRobotOptions.MissingAfterCycles"/> missed replies in a row) and answer
/// again, and the live faults (module missing, bus degraded, current limited).
/// </summary>
public sealed class FeedbackExchangeTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void A_module_counts_as_missing_after_exactly_the_configured_missed_replies_and_is_reported_once()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { MissingAfterCycles = 4 });
        var robot = rig.Robot;
        rig.Cycles(3);
        var module = robot.Controller(12)!;

        rig.Sim.ScheduleTransmitBreak(12, rig.Sim.Elapsed); // it still hears, it is no longer heard
        for (var missed = 1; missed <= 3; missed++)
        {
            robot.RunCycle();
            Assert.Equal(missed, module.MissedReplies);
            Assert.True(module.Present);
            Assert.True(robot.Faults.HasFlag(RobotFaults.BusDegraded));
            Assert.False(robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        }

        robot.RunCycle();
        Assert.False(module.Present);
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        rig.Cycles(6);
        Assert.Equal(10, module.MissedReplies);
        Assert.Equal([new ModuleStoppedAnswering(12, "left upper arm")], rig.Events<ModuleStoppedAnswering>());
        Assert.All(robot.Controllers.Where(c => c.Id != 12), c => Assert.Equal((true, 0), (c.Present, c.MissedReplies)));
    }

    [Fact]
    public void Modules_that_missed_exactly_enough_replies_count_as_present_again_at_their_next_reply()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(3);

        rig.Tap.Deaf = true; // three cycles without a reply from anyone: each module misses the default three
        rig.Cycles(3);
        Assert.All(robot.Controllers, c => Assert.False(c.Present));
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleMissing | RobotFaults.BusDegraded));

        rig.Tap.Deaf = false;
        robot.RunCycle();
        Assert.All(robot.Controllers, c => Assert.Equal((true, 0), (c.Present, c.MissedReplies)));
        Assert.Equal(robot.Controllers.Select(c => c.Id).Order(), rig.Events<ModuleAnswersAgain>().Select(e => e.ModuleId).Order());
        Assert.Equal(RobotFaults.None, robot.Faults & (RobotFaults.ModuleMissing | RobotFaults.BusDegraded));
    }

    [Fact]
    public void The_arms_currents_are_their_motors_currents_in_robot_file_order()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.StallElbow(1, 20 * Deg);
        robot.RunFor(TimeSpan.FromMilliseconds(200));

        var actuators = robot.Definition.Actuators;
        Span<double> currents = stackalloc double[actuators.Count];
        for (var arm = 0; arm < 2; arm++)
        {
            robot.ReadMotorCurrents(arm, currents);
            for (var k = 0; k < actuators.Count; k++)
            {
                var motor = robot.Motors.Single(m => m.Config.Arm == arm && m.Config.Actuator == actuators[k]);
                Assert.Equal(motor.CurrentA, currents[k]);
            }
        }

        robot.ReadMotorCurrents(1, currents);
        Assert.True(currents[actuators.ToList().FindIndex(a => a.Name == "elbow")] > 0.5 * robot.Motor("left.elbow").CurrentLimitA, "the stalled elbow draws current");
    }

    [Fact]
    public void A_motor_counts_as_current_limited_from_the_configured_fraction_of_its_limit_while_it_lasts()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { CurrentLimitedFraction = 0.5 });
        var robot = rig.Robot;
        rig.Cycles(20);
        Assert.Equal(RobotFaults.None, robot.Faults); // at rest: nothing limited, nothing missing

        // A current sense reading 70 % of the limit (the firmware's own limit does not engage), on one motor, then two.
        var right = rig.Sim.Axis(0, "elbow");
        var left = rig.Sim.Axis(1, "elbow");
        var limit = robot.Motor("right.elbow").CurrentLimitA;
        right.CurrentSenseOffsetA = 0.7 * limit;
        rig.Cycles(40);
        Assert.True(robot.Faults.HasFlag(RobotFaults.CurrentLimited));
        left.CurrentSenseOffsetA = 0.7 * limit;
        rig.Cycles(40);
        Assert.True(robot.Faults.HasFlag(RobotFaults.CurrentLimited));
        Assert.All(robot.Controllers, c => Assert.Equal(0, c.HardwareErrorStatus & 1)); // no over-current latched in any module

        right.CurrentSenseOffsetA = 0;
        left.CurrentSenseOffsetA = 0;
        rig.Cycles(40);
        Assert.Equal(RobotFaults.None, robot.Faults);
    }

    [Fact]
    public void A_configured_module_that_is_missing_stays_a_live_fault_while_the_others_cycle()
    {
        // Two modules of the file are not on the bus (IDs 20 and 21).
        var view = VirtualLb.EditedLb(json =>
        {
            foreach (var m in json["modules"]!["layout"]!.AsArray())
            {
                var id = (int)m!["id"]!;
                if (id is 12 or 13)
                {
                    m["id"] = id + 8;
                }
            }
        });
        using var rig = new TappedLb(hostView: view);
        Assert.Equal([20, 21], rig.Discovery!.Missing.Select(c => (int)c.Id).Order());
        rig.Cycles(20);
        Assert.True(rig.Robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        Assert.False(rig.Robot.Faults.HasFlag(RobotFaults.BusDegraded));
    }

    [Fact]
    public void The_status_poll_runs_on_schedule_and_a_new_alert_brings_it_forward()
    {
        var statusAddress = ControlTable.Firmware["hardware_error_status"].At(0);
        using var rig = new TappedLb(options: new BusRobotOptions { StatusPollCycles = 5 });
        var robot = rig.Robot;
        int Polls() => rig.Tap.Sent.Count(f => f.Instruction == Instruction.SyncRead && f.Address == statusAddress);
        Assert.Equal(0, robot.Cycles);
        rig.Cycles(14);
        Assert.Equal(2, Polls()); // cycles 5 and 10

        // The watchdogs trip while the host is silent: the next replies carry the alert, so the poll comes at once.
        rig.SilenceBeyondTheWatchdog();
        rig.Cycles(1); // cycle 15: a scheduled poll as well
        rig.Cycles(1); // cycle 16
        Assert.True(robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        var polls = Polls();

        // Known errors are polled on schedule again, not at every alert.
        rig.Cycles(3); // cycles 17 to 19
        Assert.Equal(polls, Polls());
    }

    [Fact]
    public void A_new_alert_is_polled_at_once_even_with_a_long_schedule()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { StatusPollCycles = 1000, ReprobeCycles = 1000 });
        var robot = rig.Robot;
        rig.Cycles(3);
        Assert.Equal(RobotFaults.None, robot.Faults);

        rig.SilenceBeyondTheWatchdog();
        rig.Cycles(2);

        Assert.True(robot.Faults.HasFlag(RobotFaults.WatchdogTripped));
        Assert.Equal(RobotState.Fault, robot.State);
        var tripped = Assert.Single(rig.Events<WatchdogTripped>()); // one event, however many modules tripped
        Assert.Equal((byte)1, tripped.ModuleId);
    }
}
