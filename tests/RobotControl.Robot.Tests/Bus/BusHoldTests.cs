using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>
/// The modules' two-stage bus watchdog as the robot layer sees it: a host silence past <c>modules.watchdog_ms</c> is a
/// hold (counted in <c>BusRobot.ModulesHolding</c>, no fault), the host's goals are refused until it acknowledges
/// (<c>BusRobot.RequestHoldAcknowledgement</c>), and arming writes both stages.
/// </summary>
public sealed class BusHoldTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Arming_writes_both_stages_of_the_robot_file_and_disarming_switches_the_watchdog_off()
    {
        using var lb = new VirtualLb();
        var modules = lb.Definition.Modules;
        Assert.True(modules.WatchdogOffMs > modules.WatchdogMs);
        Assert.All(modules.Modules, m => Assert.Equal((modules.WatchdogMs, modules.WatchdogOffMs), Stages(lb, m.Id)));

        lb.Robot.EnableTorque(false);
        Assert.All(modules.Modules, m => Assert.Equal((0, modules.WatchdogOffMs), Stages(lb, m.Id))); // stage 1 0: both off
        lb.Robot.EnableTorque(true);
        Assert.All(modules.Modules, m => Assert.Equal((modules.WatchdogMs, modules.WatchdogOffMs), Stages(lb, m.Id)));
    }

    [Fact]
    public void A_short_host_silence_is_a_hold_the_goals_are_refused_until_acknowledged_and_nothing_steps()
    {
        using var lb = new VirtualLb();
        var present = lb.Robot.Controllers.Count(c => c.Present);
        lb.Robot.WriteJointSetpoints(0, [-40 * Deg, 0, 0, 120 * Deg, 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(100));
        var elbow = lb.Sim.Axis(0, "elbow");

        lb.Sim.Advance(TimeSpan.FromMilliseconds(lb.Definition.Modules.WatchdogMs + 20)); // the host stalls
        var held = elbow.OutputAngleRad;
        Assert.True(120 * Deg - held > 10 * Deg, "the elbow had arrived before the stall");
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(300)); // the host is back, still sending the goals toward 120 degrees
        Assert.Equal(present, lb.Robot.ModulesHolding);
        Assert.All(lb.Robot.Controllers, c => Assert.True(c.BusHold, $"{c} not holding"));
        Assert.Equal(present, lb.Robot.Events.History().OfType<ModuleHolding>().Count());
        Assert.All(lb.Sim.Axes, a => Assert.True(a.DriverEnabled)); // a hold, and stage 2 stays away while the host talks
        Assert.Equal(RobotFaults.None, lb.Robot.Faults & ~RobotFaults.CurrentLimited);
        Assert.Equal(RobotState.Enabled, lb.Robot.State);
        Assert.InRange(elbow.OutputAngleRad - held, -1 * Deg, 1 * Deg); // the goals toward 120 degrees were refused

        // Acknowledged with the goals held at the measured positions: the modules take goals again, nothing steps.
        lb.Robot.HoldAtMeasured();
        lb.Robot.RequestHoldAcknowledgement();
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(50));
        Assert.Equal(0, lb.Robot.ModulesHolding);
        Assert.All(lb.Robot.Controllers, c => Assert.False(c.BusHold));
        Assert.Equal(present, lb.Robot.Events.History().OfType<HoldAcknowledged>().Count());
        Assert.InRange(elbow.OutputAngleRad - held, -1 * Deg, 1 * Deg);

        lb.Robot.ReleaseHold();
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(300));
        Assert.True(elbow.OutputAngleRad - held > 5 * Deg, "the elbow follows its setpoint again");
    }

    [Fact]
    public void Acknowledged_without_a_hold_the_goals_resume_from_where_the_modules_held_under_the_step_cap()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [-40 * Deg, 0, 0, 120 * Deg, 0]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(100));
        lb.Sim.Advance(TimeSpan.FromMilliseconds(lb.Definition.Modules.WatchdogMs + 20));
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(300)); // the goals sent run on toward 120 degrees, refused
        var elbow = lb.Robot.Motor("right.elbow");
        Assert.True(lb.Robot.SentGoalRad(elbow) - elbow.PositionRad > 10 * Deg);

        lb.Robot.RequestHoldAcknowledgement();
        lb.Robot.RunCycle();
        Assert.Equal(0, lb.Robot.ModulesHolding);
        Assert.InRange(lb.Robot.SentGoalRad(elbow) - elbow.PositionRad, 0, 1 * Deg); // one step cap from the held position
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(500));
        Assert.InRange(elbow.PositionRad - (120 * Deg), -1 * Deg, 1 * Deg);
    }

    [Fact]
    public void The_robot_files_watchdog_bounds_are_the_control_tables()
    {
        foreach (var name in new[] { "bus_watchdog", "bus_watchdog_off" })
        {
            Assert.Equal(0, ControlTable.Firmware[name].Min);
            Assert.Equal(ModuleLayout.MaxWatchdogMs, ControlTable.Firmware[name].Max);
        }
    }

    private static (int Stage1, int Stage2) Stages(VirtualLb lb, byte id)
    {
        Span<byte> two = stackalloc byte[2];
        lb.Sim.PeekTable(id, ControlTable.Firmware["bus_watchdog"].At(0), two);
        var stage1 = BinaryPrimitives.ReadUInt16LittleEndian(two);
        lb.Sim.PeekTable(id, ControlTable.Firmware["bus_watchdog_off"].At(0), two);
        return (stage1, BinaryPrimitives.ReadUInt16LittleEndian(two));
    }
}
