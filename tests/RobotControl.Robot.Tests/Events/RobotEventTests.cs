using System.Text.Json.Nodes;
using RobotControl.Bus.Protocol;
using RobotControl.TestSupport;
using RobotControl.Definitions.Loading;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Events;

namespace RobotControl.Robot.Tests.Events;

public sealed class RobotEventTests
{
    [Fact]
    public void A_discovery_problem_is_one_typed_event_per_finding()
    {
        using var lb = new VirtualLb(hostView: VirtualLb.MisconfiguredHostView());
        var problems = lb.Robot.Events.History().OfType<DiscoveryProblemEvent>().Select(e => e.Problem).ToList();
        Assert.Equal(lb.Discovery!.Problems, problems);
        var missing = Assert.Single(problems, p => p.Kind == DiscoveryProblemKind.Missing);
        Assert.Equal((byte)20, missing.ModuleId);
        Assert.Equal([(byte)3, (byte)13], problems.Where(p => p.Kind == DiscoveryProblemKind.Unknown).Select(p => p.ModuleId!.Value).Order());
        Assert.DoesNotContain(lb.Robot.Events.History(), e => e.Message.StartsWith("found", StringComparison.Ordinal));
        Assert.Equal(lb.Discovery.Lines().Where(l => !l.StartsWith("found", StringComparison.Ordinal)), problems.Select(p => p.Line));
    }

    [Fact]
    public void Event_messages_read_as_one_line_each()
    {
        Assert.Equal("module 2 \"right shoulder\" reset (brown-out); resumed its position from FRAM", new ModuleResetEvent(2, "right shoulder", "brown-out", true, false).ToString());
        Assert.Equal(
            "module 2 \"x\" reset (watchdog); had no position record and homed from its pot; its position disagrees with the pot: motors left off",
            new ModuleResetEvent(2, "x", "watchdog", false, true).Message);
        Assert.Equal("module 4 \"x\": bus watchdog tripped, motors stopped", new WatchdogTripped(4, "x").Message);
        Assert.Equal("module 4 \"x\": bus silent for its watchdog's first stage, holding its motors; goals refused until the hold is acknowledged", new ModuleHolding(4, "x").Message);
        Assert.Equal("module 4 \"x\": hold acknowledged, following the goals again", new HoldAcknowledged(4, "x").Message);
        Assert.Equal("module 4 \"x\": hardware error hall, pot_mismatch", new HardwareErrorLatched(4, "x", HardwareErrors.Hall | HardwareErrors.PotMismatch).Message);
        Assert.Equal("bus error: gone", new BusError("gone").Message);
    }

    [Fact]
    public void Error_bits_and_reset_causes_come_from_the_control_table()
    {
        var table = ControlTable.Firmware;
        var status = table.Bits("hardware_error_status");
        Assert.Equal(1 << status["pot_mismatch"], HardwareErrors.PotMismatch.Value);
        Assert.Equal(1 << status["bus_watchdog"], HardwareErrors.BusWatchdog.Value);
        Assert.Equal(1 << status["bus_hold"], HardwareErrors.BusHold.Value);
        Assert.Equal(7, status.Count);
        Assert.All(table.Bits("motor_error"), b => Assert.Equal(status[b.Key], b.Value)); // motor_error shares the module's bits
        Assert.Equal("brown-out", table.Codes("reset_cause")[2]);
        Assert.Empty(table.Codes("kp"));
        Assert.Equal(1_000_000, ModuleParameters.BaudFromCode((int)table["baud_rate"].Default));
        Assert.All(table.Codes("baud_rate"), c => Assert.Equal(c.Key, ModuleParameters.BaudCode(int.Parse(c.Value, System.Globalization.CultureInfo.InvariantCulture))));
        Assert.Equal("none", HardwareErrors.None.ToString());
        Assert.Equal("over_current, position_lost", (HardwareErrors.OverCurrent | HardwareErrors.PositionLost).ToString());
        Assert.Throws<KeyNotFoundException>(() => table.Bit("hardware_error_status", "no_such_bit"));
    }
}
