using RobotControl.Host.Harness;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Simulation.Time;

namespace RobotControl.Host.Tests.Harness;

/// <summary>The device faults of <c>--inject</c> find their instance through the SDK's <see cref="IFaultInjectable"/> seam, by name, in the loaded graph.</summary>
public sealed class DeviceFaultTargetsTests
{
    private static IReadOnlyList<Plugin> Instances() =>
        GraphFile.Load(Graphs.Path("teleop-lb.json"), TestPlugins.Catalog(), new ManualTimeProvider()).Program.Order;

    private static TimedFault Fault(string text) => FaultInjection.Parse(text).TimedFaults.Single();

    [Fact]
    public void A_jump_and_a_stale_fault_reach_the_named_instance_as_the_sdks_device_faults()
    {
        var instances = Instances();

        var target = DeviceFaultTargets.Resolve(Fault("jump=touch_left:-25mm@2s"), instances);

        Assert.Same(instances.Single(p => p.Name == "touch_left"), target);
        var jump = DeviceFaultTargets.FaultOf(Fault("jump=touch_left:-25mm@2s"));
        Assert.Equal((DeviceFaultKind.Jump, -25.0), (jump.Kind, jump.JumpXMm));
        Assert.Same(DeviceFault.Stale, DeviceFaultTargets.FaultOf(Fault("stale=touch_right@1s")));
        Assert.Same(instances.Single(p => p.Name == "touch_right"), DeviceFaultTargets.Resolve(Fault("stale=touch_right@1s"), instances));
    }

    [Theory]
    [InlineData("stale=ik_right@1s", "--inject 'stale=ik_right@1s': plug-in 'ik_right' cannot take stale faults (plug-ins that take them: touch_right, touch_left)")]
    [InlineData("jump=clutch_left:5mm@1s", "--inject 'jump=clutch_left:5mm@1s': plug-in 'clutch_left' cannot take jump faults (plug-ins that take them: touch_right, touch_left)")]
    [InlineData("stale=touch_middle@1s", "--inject 'stale=touch_middle@1s': no plug-in 'touch_middle' in the graph (plug-ins that take stale faults: touch_right, touch_left)")]
    public void A_fault_aimed_at_an_instance_that_cannot_take_it_is_refused_in_one_line(string inject, string message)
    {
        var error = Assert.Throws<FormatException>(() => DeviceFaultTargets.Resolve(Fault(inject), Instances()));

        Assert.Equal(message, error.Message);
    }

    [Fact]
    public void Only_jump_and_stale_are_device_faults()
    {
        Assert.Equal(
            [false, false, false, false, false, false, false, true, true],
            FaultInjection.Parse("silent=right.forearm@1s,watchdog=right.forearm@1s,stall=5ms@1s,stuck=right.elbow@1s,current=right.elbow@1s,nan=ik_right@1s,pot=right.elbow@1s,jump=touch_right:5mm@1s,stale=touch_right@1s")
                .TimedFaults.Select(DeviceFaultTargets.IsDeviceFault));
        Assert.Throws<ArgumentOutOfRangeException>(() => DeviceFaultTargets.FaultOf(Fault("nan=ik_right@1s")));
    }
}
