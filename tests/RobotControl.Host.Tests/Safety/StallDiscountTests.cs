using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// A host stall is not observed time (<c>MotorChecks.Discount</c>): a condition seen just before a stall must persist
/// its time again after it, on the virtual robot (teleop graph).
/// </summary>
public sealed class StallDiscountTests
{
    [Fact]
    public void An_over_current_seen_10_ms_before_a_300_ms_stall_needs_the_rest_of_its_50_ms_after_the_stall()
    {
        // The current goes over its limit at 1.000 s and stays; the host stalls 300 ms from 1.010 s. Without the
        // discount the 300 ms would count as persisted and over_current would trip with the stall's first check.
        var run = SafetyRun.Of("current=right.elbow@1s,stall=300ms@1010ms", 1.5);

        var stall = run.Trip(SafetyCheck.HostStall);
        Assert.True(stall.Soft, "300 ms is short of the modules' torque-off stage");
        var over = run.Trip(SafetyCheck.OverCurrent);
        Assert.Equal("right.elbow", over.Joint);
        Assert.False(over.Soft);
        var after = over.TimeSeconds - stall.TimeSeconds;
        Assert.InRange(after, 0.030, 0.052); // 50 ms less the ~10 ms seen before the stall (and what of the stall's first 10 ms counts)
    }
}
