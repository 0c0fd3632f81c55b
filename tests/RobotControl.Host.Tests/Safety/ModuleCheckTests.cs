using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// The per-module watchdog check on a supervised virtual LB: while the motors are on at PEDAL_UP or PEDAL_DOWN, a
/// module's bus watchdog read back as off or another period than the robot file's is an E_STOP with the motors off.
/// </summary>
public sealed class ModuleCheckTests
{
    private static readonly ushort WatchdogAddress = ControlTable.Firmware["bus_watchdog"].At(0);

    [Theory]
    [InlineData(0)]
    [InlineData(45)]
    public void A_bus_watchdog_read_back_off_or_at_another_period_trips_watchdog_unarmed(byte periodMs)
    {
        using var lb = new SupervisedLb();
        _ = lb.Sim.WriteTable(3, WatchdogAddress, [periodMs, 0]);
        lb.CyclesUntil(() => lb.Supervisor.Trips.Count > 0, TimeSpan.FromMilliseconds(50)); // the status poll reads it back

        var trip = Assert.Single(lb.Supervisor.Trips);
        Assert.Equal((SafetyCheck.WatchdogUnarmed, "right.forearm", (double)periodMs, 30.0, "ms", SafeState.TorqueOff, false), (trip.Check, trip.Joint, trip.Measured, trip.Limit, trip.Unit, trip.Action, trip.Soft));
        Assert.Equal((RunLevel.PedalUp, RunLevel.EStop, "supervisor", "watchdog_unarmed right.forearm: torque_off"), lb.LastMove);
    }

    [Fact]
    public void The_bus_watchdog_is_not_checked_with_the_motors_off_nor_at_e_stop()
    {
        using var lb = new SupervisedLb();
        lb.Supervisor.MotorsOff("console");
        _ = lb.Sim.WriteTable(3, WatchdogAddress, [0, 0]);
        lb.CyclesFor(TimeSpan.FromMilliseconds(50));
        Assert.Empty(lb.Supervisor.Trips);

        lb.Supervisor.Home("console"); // the motors on arm every watchdog again
        lb.CyclesFor(TimeSpan.FromMilliseconds(50));
        Assert.Empty(lb.Supervisor.Trips);

        lb.StopNow(); // holds: the motors stay on
        _ = lb.Sim.WriteTable(3, WatchdogAddress, [0, 0]);
        lb.CyclesFor(TimeSpan.FromMilliseconds(50));
        Assert.Equal(SafetyCheck.Operator, Assert.Single(lb.Supervisor.Trips).Check);
    }
}
