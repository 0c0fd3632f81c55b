using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// The module work after each publish: the joint pots, each module's detail in turn, the search for missing modules,
/// resets (re-armed, or a fault when the position disagrees with the pot), latched errors and the over-current
/// acknowledgement, and clearing faults in the modules.
/// </summary>
public sealed class ModuleSupervisorTests
{
    private const double Deg = Math.PI / 180;
    private static readonly ControlTable Table = ControlTable.Firmware;

    [Fact]
    public void The_pots_are_read_on_their_schedule_and_each_motor_gets_its_own_pot_position()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { PotPollCycles = 4 });
        var robot = rig.Robot;
        int PotReads() => rig.Tap.Sent.Count(f => f.Instruction == Instruction.SyncRead && f.Address == Table["pot_raw"].At(0));

        robot.RunCycle();
        Assert.All(robot.Motors, m => Assert.True(double.IsNaN(m.PotPositionRad)));
        robot.RunCycle(); // cycle 2: half-way through the period
        Assert.Equal(1, PotReads());
        var read = rig.Tap.Sent.Single(f => f.Instruction == Instruction.SyncRead && f.Address == Table["pot_raw"].At(0));
        Assert.Equal(6, BinaryPrimitives.ReadUInt16LittleEndian(read.Parameters.AsSpan(2))); // the pots of three channels, the widest module's
        Assert.Equal([1, 2, 3, 11, 12, 13], read.Parameters[4..].Select(b => (int)b));
        rig.Cycles(9);
        Assert.Equal(3, PotReads()); // cycles 2, 6 and 10

        foreach (var m in robot.Motors)
        {
            Assert.InRange(m.PotPositionRad - m.PositionRad, -1.5 * Deg, 1.5 * Deg);
        }
    }

    [Fact]
    public void No_pot_poll_when_switched_off_and_a_silent_module_keeps_its_pots_unknown()
    {
        using (var off = new TappedLb(options: new BusRobotOptions { PotPollCycles = 0 }))
        {
            off.Cycles(20);
            Assert.DoesNotContain(off.Tap.Sent, f => f.Address == Table["pot_raw"].At(0));
            Assert.All(off.Robot.Motors, m => Assert.True(double.IsNaN(m.PotPositionRad)));
        }

        using var rig = new TappedLb(options: new BusRobotOptions { PotPollCycles = 2, MissingAfterCycles = 1000 });
        rig.Sim.ScheduleTransmitBreak(3, rig.Sim.Elapsed);
        rig.Cycles(6);
        Assert.All(rig.Robot.Motors, m => Assert.Equal(m.Controller.Id == 3, double.IsNaN(m.PotPositionRad)));
    }

    [Fact]
    public void The_detail_poll_reads_one_module_in_turn_on_its_schedule()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { DetailPollCycles = 4 });
        var robot = rig.Robot;
        rig.Cycles(10); // cycles 1, 5 and 9: the first three modules
        Assert.All(robot.Motors, m => Assert.Equal(m.Controller.Id < 10 ? true : null, m.TorqueReadBack));
        Assert.All(robot.Motors, m => Assert.Equal(m.Controller.Id < 10 ? HardwareErrors.None : null, m.Errors));

        rig.Cycles(16); // three more: every module read once
        Assert.All(robot.Motors, m => Assert.True(m.TorqueReadBack));

        robot.EnableTorque(false);
        rig.Cycles(24);
        Assert.All(robot.Motors, m => Assert.False(m.TorqueReadBack));
    }

    [Fact]
    public void A_module_that_does_not_answer_the_detail_poll_has_no_detail()
    {
        using var rig = new TappedLb(
            options: new BusRobotOptions { DetailPollCycles = 1 },
            beforeStart: tap => tap.Lose = f => f.Id == 3 && (f.IsRead(3, Table["torque_enable"].At(0)) || f.IsRead(3, Table["motor_error"].At(0))));
        rig.Cycles(6);
        Assert.All(rig.Robot.Motors, m => Assert.Equal(m.Controller.Id == 3 ? null : true, m.TorqueReadBack));
        Assert.All(rig.Robot.Motors, m => Assert.Equal(m.Controller.Id == 3 ? null : HardwareErrors.None, m.Errors));
    }

    [Fact]
    public void A_module_missing_at_discovery_is_searched_for_on_schedule_and_takes_part_once_found()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { ReprobeCycles = 10 }, beforeStart: tap => tap.Mute(12));
        var robot = rig.Robot;
        var module = robot.Controller(12)!;
        Assert.Equal([12], rig.Discovery!.Missing.Select(c => (int)c.Id));
        rig.Tap.ClearSent();
        int Pings(byte id) => rig.Tap.Sent.Count(f => f.Instruction == Instruction.Ping && f.Id == id);

        rig.Cycles(10);
        var perSearch = Pings(12); // cycle 10, with the client's retries
        Assert.True(perSearch >= 1);
        rig.Cycles(15);
        Assert.Equal(2 * perSearch, Pings(12)); // and cycle 20
        Assert.All(robot.Controllers.Where(c => c.Id != 12), c => Assert.Equal(0, Pings(c.Id)));
        Assert.False(module.Present);
        Assert.True(robot.Faults.HasFlag(RobotFaults.ModuleMissing));

        rig.Tap.Unmute();
        rig.Cycles(5); // cycle 30 finds it
        Assert.Equal(2 * perSearch + 1, Pings(12));
        Assert.True(module.Present);
        Assert.Equal([new ModuleAnswersAgain(12, "left upper arm")], rig.Events<ModuleAnswersAgain>());
        rig.Cycles(1);
        Assert.False(robot.Faults.HasFlag(RobotFaults.ModuleMissing));
        Assert.InRange(robot.Motor("left.elbow").PositionRad - rig.Sim.Axis(1, "elbow").OutputAngleRad, -1 * Deg, 1 * Deg);
        rig.Cycles(20);
        Assert.Equal(2 * perSearch + 1, Pings(12)); // present: not searched for again
    }

    [Fact]
    public void A_reset_with_a_cause_the_table_does_not_name_is_reported_by_its_code()
    {
        using var rig = new TappedLb();

        // Firmware newer than the host's table: its status poll gives a reset cause the table has no name for.
        var statusAddress = Table["hardware_error_status"].At(0);
        rig.Tap.Rewrite = (request, reply) => request?.Address == statusAddress && reply.Parameters.Length == 4 && reply.Parameters[1] != 0
            ? reply with { Parameters = [reply.Parameters[0], 9, reply.Parameters[2], reply.Parameters[3]] }
            : null;
        rig.Sim.ScheduleReset(2, rig.Sim.Elapsed + TimeSpan.FromMilliseconds(1));
        rig.Robot.RunFor(TimeSpan.FromMilliseconds(50));

        var reset = Assert.Single(rig.Events<ModuleResetEvent>());
        Assert.Equal("cause 9", reset.Cause);
        Assert.Equal(9, rig.Robot.Controller(2)!.LastResetCause);
    }

    [Fact]
    public void A_module_that_falls_silent_right_after_a_reset_is_not_reported_resetting_again()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        var module = robot.Controller(2)!;
        rig.Sim.ScheduleReset(2, rig.Sim.Elapsed + TimeSpan.FromMilliseconds(1));
        for (var i = 0; i < 100 && module.Resets == 0; i++)
        {
            robot.RunCycle();
        }

        Assert.Equal(1, module.Resets);
        rig.Tap.Mute(2);
        rig.Cycles(24); // three status polls that module 2 does not answer
        Assert.Equal(1, module.Resets);
        Assert.Single(rig.Events<ModuleResetEvent>());
    }

    [Fact]
    public void A_module_whose_status_cannot_be_read_at_discovery_takes_no_other_modules_status()
    {
        var statusAddress = Table["hardware_error_status"].At(0);
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        var shoulder = rig.Sim.Axis(0, "shoulder_1");
        rig.Sim.TurnWhileOff(shoulder, shoulder.OutputAngleRad + (25 * Deg)); // module 1 starts with a pot mismatch
        rig.Sim.Advance(TimeSpan.FromMilliseconds(2));
        rig.Tap.Lose = f => f.IsRead(2, statusAddress);

        robot.Discover();

        Assert.True(((HardwareErrors)(long)robot.Controller(1)!.HardwareErrorStatus).HasAny(HardwareErrors.PotMismatch));
        Assert.Equal(0, robot.Controller(2)!.HardwareErrorStatus);
        Assert.DoesNotContain(rig.Tap.Sent, f => f.IsWrite(2, Table["reset_cause"].At(0)));
        Assert.Contains(rig.Tap.Sent, f => f.IsWrite(1, Table["reset_cause"].At(0)));
    }

    [Fact]
    public void A_module_reset_while_the_motors_are_off_is_not_armed()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        robot.EnableTorque(false);
        rig.Sim.ScheduleReset(2, rig.Sim.Elapsed + TimeSpan.FromMilliseconds(1));
        robot.RunFor(TimeSpan.FromMilliseconds(50));

        Assert.Equal(1, robot.Controller(2)!.Resets);
        Assert.Equal(0, robot.ReadParameter(2, "torque_enable"));
        Assert.Equal(0, robot.ReadParameter(2, "bus_watchdog"));
        Assert.Equal(RobotState.Discovered, robot.State);
    }

    [Fact]
    public void A_module_that_resets_with_its_position_off_its_pot_is_a_fault_and_left_off()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(5);
        var elbow = rig.Sim.Axis(0, "elbow");

        rig.Sim.TurnWhileOff(elbow, elbow.OutputAngleRad + (25 * Deg)); // a power cycle: the module resumes a stale position
        robot.RunFor(TimeSpan.FromMilliseconds(50));

        var reset = Assert.Single(rig.Events<ModuleResetEvent>());
        Assert.True(reset.PotMismatch);
        Assert.Empty(rig.Events<HardwareErrorLatched>()); // told once, as the reset
        Assert.True(robot.Faults.HasFlag(RobotFaults.HardwareError | RobotFaults.ModuleReset));
        Assert.Equal(RobotState.Fault, robot.State);
        Assert.Equal("module 2 \"right upper arm\" reset and its position disagrees with the pot", robot.StateHistory[^1].Reason);
        Assert.Equal(0, robot.ReadParameter(2, "torque_enable"));
        Assert.False(elbow.DriverEnabled);
    }

    [Fact]
    public void The_reset_a_module_reports_at_start_up_is_kept_as_its_last_reset_before_the_host_connected_and_a_later_one_replaces_it()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        rig.Sim.Advance(TimeSpan.FromMilliseconds(2));

        robot.Discover();

        var module = robot.Controller(2)!;
        Assert.Equal(1, module.LastResetCause); // power-on: the module started when the virtual robot did
        Assert.True(module.LastResetBeforeConnect);
        Assert.Equal(0, module.Resets); // history, not a reset this session
        Assert.Equal(0, robot.ReadParameter(2, "reset_cause")); // and cleared in the module
        Assert.Empty(rig.Events<ModuleResetEvent>());

        robot.RunFor(TimeSpan.FromMilliseconds(5));
        rig.Sim.ScheduleReset(2, rig.Sim.Elapsed + TimeSpan.FromMilliseconds(1));
        robot.RunFor(TimeSpan.FromMilliseconds(50));

        var reset = Assert.Single(rig.Events<ModuleResetEvent>());
        Assert.Equal(reset.Cause, RobotControl.Bus.Protocol.ControlTable.Firmware.Codes("reset_cause")[module.LastResetCause]);
        Assert.False(module.LastResetBeforeConnect);
        Assert.Equal(1, module.Resets);
    }

    [Fact]
    public void A_pot_mismatch_found_at_start_up_is_a_hardware_error_until_faults_are_cleared()
    {
        using var rig = new TappedLb(start: false);
        var robot = rig.Robot;
        var elbow = rig.Sim.Axis(0, "elbow");
        rig.Sim.TurnWhileOff(elbow, elbow.OutputAngleRad + (25 * Deg)); // before the host connects
        rig.Sim.Advance(TimeSpan.FromMilliseconds(2));

        robot.Discover();
        var module = robot.Controller(2)!;
        Assert.True(((HardwareErrors)(long)module.HardwareErrorStatus).HasAny(HardwareErrors.PotMismatch));
        Assert.Equal(0, robot.ReadParameter(2, "reset_cause")); // the reset before the host came is history, not news
        robot.RunFor(TimeSpan.FromMilliseconds(30));

        var latched = Assert.Single(rig.Events<HardwareErrorLatched>());
        Assert.Equal((byte)2, latched.ModuleId);
        Assert.True(latched.Errors.HasAny(HardwareErrors.PotMismatch));
        Assert.Empty(rig.Events<ModuleResetEvent>());
        Assert.True(robot.Faults.HasFlag(RobotFaults.HardwareError));
        Assert.Equal(RobotState.Fault, robot.State);
        Assert.Equal(($"module 2 \"right upper arm\": hardware error {latched.Errors}", "modules"), (robot.StateHistory[^1].Reason, robot.StateHistory[^1].Source));

        robot.ClearFaults();
        robot.RunFor(TimeSpan.FromMilliseconds(5));
        Assert.Equal(RobotState.Discovered, robot.State); // the motors were off: back to where they were
        Assert.False(robot.Faults.HasFlag(RobotFaults.HardwareError));
    }

    [Fact]
    public void Over_current_alone_is_acknowledged_in_the_module_and_shows_as_current_limited()
    {
        using var rig = new TappedLb(options: new BusRobotOptions { CurrentLimitedFraction = 10 }); // only the modules' bit says limited
        var robot = rig.Robot;
        rig.StallElbow(0, 30 * Deg);
        var sawLimited = 0;
        for (var i = 0; i < 300; i++)
        {
            robot.RunCycle();
            sawLimited += robot.Faults.HasFlag(RobotFaults.CurrentLimited) ? 1 : 0;
            Assert.Equal(0, robot.Controller(2)!.HardwareErrorStatus); // acknowledged at each poll that finds it
        }

        Assert.True(sawLimited > 0);
        Assert.Contains(rig.Tap.Sent, f => f.IsWrite(2, Table["hardware_error_status"].At(0)) && f.Parameters.Length == 3);
        Assert.DoesNotContain(rig.Tap.Sent, f => f.Instruction == Instruction.Write && f.Id != 2 && f.Address == Table["hardware_error_status"].At(0));
        Assert.Equal(RobotState.Enabled, robot.State);
    }

    [Fact]
    public void Clearing_faults_re_arms_the_modules_and_reports_one_that_refuses()
    {
        using var rig = new TappedLb();
        var robot = rig.Robot;
        rig.Cycles(3);
        rig.SilenceBeyondTheWatchdog();
        rig.Cycles(2);
        Assert.Equal(RobotState.Fault, robot.State);

        // Module 13 never hears the clear: its watchdog error stays latched and it refuses the motors on.
        rig.Tap.Lose = f => f.IsWrite(13, Table["hardware_error_status"].At(0));
        robot.ClearFaults();
        robot.Write();

        var refused = Assert.Single(rig.Events<TorqueRefused>());
        Assert.Contains("module 13", refused.Message, StringComparison.Ordinal);
        Assert.Contains("watchdog error is latched", refused.Message, StringComparison.Ordinal);
        Assert.Equal(RobotState.Enabled, robot.State);
        Assert.Equal(RobotFaults.None, robot.Faults & RobotFaults.WatchdogTripped);
        rig.Sim.Advance(TimeSpan.FromMilliseconds(1));
        Assert.All(rig.Sim.Axes, a => Assert.Equal(a.Config.ModuleId != 13, a.DriverEnabled));
    }
}
