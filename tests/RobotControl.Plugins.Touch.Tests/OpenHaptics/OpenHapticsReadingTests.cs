using RobotControl.Plugins.Touch.OpenHaptics;
using RobotControl.TestSupport;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

[Collection(FakeHdCollection.Name)]
public sealed class OpenHapticsReadingTests
{
    public OpenHapticsReadingTests() => FakeHdLibrary.Reset();

    [Fact]
    public void Scripted_positions_and_buttons_arrive_in_the_device_frame_in_mm()
    {
        FakeHdLibrary.Key("right", 0, 10, -20, 30, yaw: 0.3);
        FakeHdLibrary.Key("right", 2000, 15, -25, 35, yaw: 0.3, buttons: 1); // stages 2 s apart: a starved test thread still reads each
        FakeHdLibrary.Key("right", 4000, 15, -25, 35, yaw: -0.2, buttons: 2);
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings()));
        touch.Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 50);
            touch.Tick();
            Assert.Equal((10.0, -20.0, 30.0), touch.Xyz());
            Assert.Equal(0.3, touch["yaw"], 9);
            Assert.Equal(0.0, touch["roll"], 9);
            Assert.Equal(0.0, touch["pitch"], 9);
            Assert.Equal((0.0, 0.0), (touch["button1"], touch["button2"]));

            FakeTouch.TickToFrame(touch, "right", 2050);
            touch.Tick();
            Assert.Equal((15.0, -25.0, 35.0), touch.Xyz());
            Assert.Equal((1.0, 0.0), (touch["button1"], touch["button2"]));

            FakeTouch.TickToFrame(touch, "right", 4050);
            touch.Tick();
            Assert.Equal(-0.2, touch["yaw"], 9);
            Assert.Equal((0.0, 1.0), (touch["button1"], touch["button2"]));
        }
        finally
        {
            touch.Plugin.Stop();
        }

        Assert.False(FakeHdLibrary.IsOpen("right"));
        Assert.False(FakeHdLibrary.SchedulerRunning);
    }

    [Fact]
    public void A_tick_on_the_device_allocates_nothing()
    {
        var touch = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings()));
        touch.Set(("force_x", 0.2)).Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 20);
            var before = GC.GetAllocatedBytesForCurrentThread();
            touch.Tick(2000);
            Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
        }
        finally
        {
            touch.Plugin.Stop();
        }
    }

    [Fact]
    public void Two_instances_run_two_devices_on_one_scheduler()
    {
        FakeHdLibrary.Key("right", 0, 1, 2, 3);
        FakeHdLibrary.Key("left", 0, -1, -2, -3);
        var right = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings("right"), "touch_right"));
        var left = new PluginDriver(FakeTouch.Plugin(FakeTouch.Settings("left"), "touch_left"));
        right.Start();
        left.Start();
        try
        {
            FakeTouch.TickUntil(right, () => FakeHdLibrary.Frames("left") > 20);
            left.Tick();
            Assert.Equal((1.0, 2.0, 3.0), right.Xyz());
            Assert.Equal((-1.0, -2.0, -3.0), left.Xyz());
        }
        finally
        {
            right.Plugin.Stop();
            Assert.True(FakeHdLibrary.SchedulerRunning); // still serving the left hand
            left.Plugin.Stop();
        }

        Assert.False(FakeHdLibrary.SchedulerRunning);
    }

    [Fact]
    public void The_same_device_cannot_be_opened_by_two_instances()
    {
        var first = FakeTouch.Plugin(FakeTouch.Settings());
        var second = FakeTouch.Plugin(FakeTouch.Settings(), "other");
        first.Start(Ticks.At(0));
        try
        {
            var ex = Assert.Throws<TouchDeviceException>(() => second.Start(Ticks.At(0)));
            Assert.Contains("already used by 'touch'", ex.Message, StringComparison.Ordinal);
        }
        finally
        {
            second.Stop();
            first.Stop();
        }
    }

    [Fact]
    public void An_init_failure_names_the_device_and_its_error()
    {
        FakeHdLibrary.FailInit("right");
        var touch = FakeTouch.Plugin(FakeTouch.Settings());

        var ex = Assert.Throws<TouchDeviceException>(() => touch.Start(Ticks.At(0)));

        Assert.Equal("'touch': cannot open the Touch device 'right': fake: device fault (HD error 0x0300, internal 42)", ex.Message);
        touch.Stop();
        Assert.False(FakeHdLibrary.SchedulerRunning);
    }

    [Fact]
    public void The_library_is_searched_in_the_setting_then_ld_library_path_then_the_system()
    {
        var file = HdLibrary.FileName;

        Assert.Equal([Path.Combine(FakeHdLibrary.Folder, file)], HdLibrary.Candidates(FakeHdLibrary.Folder, "/a"));
        Assert.Equal(["/opt/x/libHD.so.3"], HdLibrary.Candidates("/opt/x/libHD.so.3", "/a"));
        Assert.Equal([Path.Combine("/a", file), Path.Combine("/b", file), file], HdLibrary.Candidates("", $"/a{Path.PathSeparator} /b "));
        Assert.Equal([file], HdLibrary.Candidates("", null));
    }
}
