using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch;
using RobotControl.TestSupport;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

/// <summary>
/// The master-jump check on the real device's back end (the fake OpenHaptics library): a reading no hand can produce is
/// reported as its speed and never reaches the pose, as with the simulated Touch (<c>TouchFaultSeamTests</c>).
/// </summary>
[Collection(FakeHdCollection.Name)]
public sealed class OpenHapticsJumpTests
{
    public OpenHapticsJumpTests() => FakeHdLibrary.Reset();

    [Fact]
    public void A_140_mm_jump_between_two_device_frames_is_reported_beyond_the_robot_file_s_limit_and_the_pose_keeps_the_last_plausible_reading()
    {
        const long jumpFrame = 1500;
        FakeHdLibrary.Key("right", 0, -70, 0, 20);
        FakeHdLibrary.Key("right", jumpFrame, 70, 0, 20); // 140 mm from one servo frame (1 ms) to the next
        var limit = ShippedRobots.Lb.Safety.MasterSpeedMaxMmPerS;
        Assert.Equal(2000, limit); // the robot file's default: 2 m/s at the device
        var touch = new PluginDriver(new TouchPlugin(FakeTouch.Settings(), PluginContext.Standalone("touch", ShippedRobots.Lb)));
        touch.Start();
        try
        {
            FakeTouch.TickToFrame(touch, "right", 100);
            touch.Tick();
            Assert.Equal((-70.0, 0.0, 20.0), touch.Xyz());
            Assert.InRange(touch["speed_mm_s"], 0, limit); // at rest

            // Tick until a reading from after the jump arrives: that tick reports the speed, the pose stays.
            FakeTouch.TickUntil(touch, () => touch["speed_mm_s"] > limit || touch["x"] > 0);
            Assert.True(touch["speed_mm_s"] > limit, $"the jump read as {touch["speed_mm_s"]} mm/s");
            Assert.Equal((-70.0, 0.0, 20.0), touch.Xyz());

            // The device stays where it jumped: the next readings are plausible again (from the jumped one) and go
            // through. Keeping the robot from following is the supervisor's part (master_jump, a soft trip: PEDAL_UP,
            // and the clutch and the IK re-anchor on re-engaging).
            FakeTouch.TickUntil(touch, () => touch["x"] > 0);
            Assert.Equal((70.0, 0.0, 20.0), touch.Xyz());
            Assert.InRange(touch["speed_mm_s"], 0, limit);
        }
        finally
        {
            touch.Plugin.Stop();
        }
    }
}
