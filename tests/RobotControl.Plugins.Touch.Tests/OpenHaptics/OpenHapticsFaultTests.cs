using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Haptics;
using RobotControl.Runtime.Graph;
using RobotControl.TestSupport;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

[Collection(FakeHdCollection.Name)]
public sealed class OpenHapticsFaultTests
{
    public OpenHapticsFaultTests() => FakeHdLibrary.Reset();

    [Theory]
    [InlineData(FakeHdLibrary.CommError, true, "fake: communication error (device unplugged) (HD error 0x0302, internal 7)")]
    [InlineData(FakeHdLibrary.ExceededMaxForce, false, "fake: exceeded the maximum force (HD error 0x0201, internal 7)")]
    public void A_device_error_faults_the_plugin_with_the_devices_text_zeroes_force_and_leaves_the_loop_running(uint code, bool unplugged, string text)
    {
        FakeHdLibrary.Key("right", 0, 10, 0, 0, buttons: 1);
        FakeHdLibrary.FailAt("right", 300, code, unplugged);
        var touch = FakeTouch.Plugin(FakeTouch.Settings());
        var damping = new ViscousDampingPlugin(new ViscousDampingSettings(), PluginContext.Standalone("damping"));
        var graph = new PluginGraph();
        graph.Add(touch);
        graph.Add(damping);
        graph.Connect("touch.x", "damping.x");
        var program = graph.Compile();
        touch.SetInput("force_x", 0.3);
        program.Start(Ticks.At(0));
        long tick = 0;
        try
        {
            FakeTouch.TickUntil(program, ref tick, () => program.IsFaulted("touch"));
            var more = 0;
            Assert.Equal(200, FakeTouch.TickUntil(program, ref tick, () => ++more > 200)); // the loop runs on

            var fault = Assert.Single(program.Faults);
            Assert.Equal("touch", fault.Instance);
            Assert.EndsWith($"'touch': the Touch device 'right' reported {text}", fault.Message, StringComparison.Ordinal);
            Assert.False(program.IsFaulted("damping"));
            Assert.Equal(0.0, touch.GetOutput("button1")); // safe value
            Assert.Equal(10.0, touch.GetOutput("x")); // held
            Assert.All(FakeHdLibrary.Forces("right").Where(f => f.Frame > 300), f => Assert.Equal(0.0, f.X));
            Assert.Contains(FakeHdLibrary.Forces("right"), f => f.Frame < 300 && f.X > 0);
        }
        finally
        {
            program.Stop();
        }

        Assert.False(FakeHdLibrary.IsOpen("right"));
        Assert.Empty(program.Faults.Skip(1)); // stopping a faulted device is clean
    }
}
