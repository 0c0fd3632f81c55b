using RobotControl.Host.Harness;

namespace RobotControl.Host.Tests.Harness;

public sealed class FaultInjectionTests
{
    [Fact]
    public void Inject_parses_the_safety_faults_and_keeps_ber_and_reset()
    {
        var f = FaultInjection.Parse("ber=1e-5,reset=right.shoulder@5s,stall=100ms@5s,stuck=right.elbow@5s,current=right.elbow@2.5s,nan=ik_right@5s,pot=right.elbow@5s");
        Assert.Equal(1e-5, f.BitErrorRate);
        Assert.Single(f.Resets);
        Assert.Equal([TimedFaultKind.Stall, TimedFaultKind.Stuck, TimedFaultKind.Current, TimedFaultKind.Nan, TimedFaultKind.Pot], f.TimedFaults.Select(t => t.Kind));
        Assert.Equal(TimeSpan.FromMilliseconds(100), f.TimedFaults[0].Duration);
        Assert.Equal(TimeSpan.FromSeconds(2.5), f.TimedFaults[2].At);
        Assert.Equal("ber=1E-05,reset=right.shoulder@5s,stall=100ms@5s,stuck=right.elbow@5s,current=right.elbow@2.5s,nan=ik_right@5s,pot=right.elbow@5s", f.ToString());
        Assert.Contains("expected stuck=<arm.motor>@<time>", Assert.Throws<FormatException>(() => FaultInjection.Parse("stuck=right.elbow")).Message, StringComparison.Ordinal);
        Assert.Contains("unknown fault", Assert.Throws<FormatException>(() => FaultInjection.Parse("melt=right.elbow@1s")).Message, StringComparison.Ordinal);
    }
}
