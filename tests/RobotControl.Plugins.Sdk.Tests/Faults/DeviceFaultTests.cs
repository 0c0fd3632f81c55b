using RobotControl.Plugins.Sdk.Faults;

namespace RobotControl.Plugins.Sdk.Tests.Faults;

public sealed class DeviceFaultTests
{
    [Fact]
    public void A_jump_carries_its_distance_and_a_stale_fault_none()
    {
        var jump = DeviceFault.Jump(-12.5);

        Assert.Equal((DeviceFaultKind.Jump, -12.5), (jump.Kind, jump.JumpXMm));
        Assert.Equal((DeviceFaultKind.Stale, 0.0), (DeviceFault.Stale.Kind, DeviceFault.Stale.JumpXMm));
        Assert.Equal(DeviceFault.Jump(-12.5), jump);
        Assert.NotEqual(DeviceFault.Jump(12.5), jump);
    }

    [Fact]
    public void A_fault_reads_as_what_happens_to_the_device()
    {
        Assert.Equal("jump 50 mm", DeviceFault.Jump(50).ToString());
        Assert.Equal("jump -0.125 mm", DeviceFault.Jump(-0.125).ToString());
        Assert.Equal("stale", DeviceFault.Stale.ToString());
    }
}
