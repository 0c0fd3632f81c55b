using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Conditioning;

/// <summary>The clutch's <c>follow</c> input (the robot's <c>teleop_enabled</c>): a soft trip holds the target, re-engaging resumes without a jump.</summary>
public sealed class ClutchFollowTests
{
    [Fact]
    public void When_the_robot_stops_following_the_target_goes_back_one_tick_holds_and_resumes_from_there_after_the_hand_moved_40_mm()
    {
        var clutch = new PluginDriver(new ClutchPlugin(new ClutchSettings(), PluginContext.Standalone("c")));
        for (var k = 0; k < 10; k++)
        {
            clutch.Set(("x", k), ("follow", 1)).Tick(); // the hand moves 1 mm per tick
        }

        Assert.Equal(9, clutch["x"]);

        // A stall: the tick that shows the robot stopped following already carries the hand's sample from after it.
        clutch.Set(("x", 30), ("follow", 1)).Tick();
        Assert.Equal(30, clutch["x"]);
        clutch.Set(("x", 31), ("follow", 0)).Tick();
        Assert.Equal(9, clutch["x"]); // back to the target of before that tick
        Assert.Equal(1, clutch["engaged"]);

        // The hand goes 40 mm further while the robot holds: the target does not move.
        for (var x = 31.0; x <= 71; x += 4)
        {
            clutch.Set(("x", x), ("follow", 0)).Tick();
            Assert.Equal(9, clutch["x"]);
        }

        // Following again: the target resumes from where it held, relative to the hand's new position.
        clutch.Set(("x", 72), ("follow", 1)).Tick();
        Assert.Equal(9, clutch["x"]);
        Assert.Equal(0, clutch["engaged"]);
        clutch.Set(("x", 73), ("follow", 1)).Tick();
        Assert.Equal(10, clutch["x"]);
    }

    [Fact]
    public void Unwired_the_clutch_follows_and_the_first_tick_ignores_the_robot_s_output_from_before_its_first_tick()
    {
        var unwired = new PluginDriver(new ClutchPlugin(new ClutchSettings(), PluginContext.Standalone("c")));
        unwired.Set(("x", 5)).Tick();
        unwired.Set(("x", 6)).Tick();
        Assert.Equal(6, unwired["x"]);

        var wired = new PluginDriver(new ClutchPlugin(new ClutchSettings(), PluginContext.Standalone("c")));
        wired.Set(("x", 5), ("follow", 0)).Tick(); // the robot's teleop_enabled before its own first tick
        wired.Set(("x", 6), ("follow", 1)).Tick();
        wired.Set(("x", 7), ("follow", 1)).Tick();
        Assert.Equal(7, wired["x"]);
    }
}
