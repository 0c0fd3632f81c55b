using RobotControl.Bus.Client;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>How a refused torque write is told: what is latched in the module, or that it did not answer.</summary>
public sealed class TorqueRefusalTests
{
    [Fact]
    public void A_refused_torque_names_the_watchdog_only_when_it_is_latched()
    {
        var refused = new Reply(ReplyOutcome.Ok, 0x04);

        var latched = TorqueRefusal.Describe(1, "m", true, refused, refused, (HardwareErrors.BusWatchdog, 0));
        var other = TorqueRefusal.Describe(1, "m", true, refused, refused, (HardwareErrors.OverCurrent, 0));
        var none = TorqueRefusal.Describe(1, "m", true, refused, refused, (HardwareErrors.None, 0));
        var silent = TorqueRefusal.Describe(1, "m", true, Reply.TimedOut, Reply.TimedOut, null);

        Assert.Contains("watchdog error is latched", latched, StringComparison.Ordinal);
        Assert.DoesNotContain("watchdog error", other, StringComparison.Ordinal);
        Assert.Contains("over_current", other, StringComparison.Ordinal);
        Assert.Contains("without a latched error", none, StringComparison.Ordinal);
        Assert.Contains("does not answer", silent, StringComparison.Ordinal);
    }
}
