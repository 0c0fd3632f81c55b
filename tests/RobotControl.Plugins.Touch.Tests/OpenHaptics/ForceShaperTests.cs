using RobotControl.Plugins.Touch.OpenHaptics;

namespace RobotControl.Plugins.Touch.Tests.OpenHaptics;

/// <summary>
/// The servo side's force shaping, frame by frame without a device or a thread: ramp, magnitude clamp, staleness and
/// the conditions that zero the force. Expected forces are worked out by hand next to each assertion.
/// </summary>
public sealed class ForceShaperTests
{
    private static (double X, double Y, double Z) Next(ForceShaper shaper, ServoCommand command, bool haveCommand = true)
    {
        var force = new double[3] { 9, 9, 9 }; // garbage the shaper must overwrite
        shaper.Next(command, haveCommand, force);
        return (force[0], force[1], force[2]);
    }

    [Fact]
    public void A_new_force_ramps_in_linearly_over_the_ramp_frames_then_holds()
    {
        // Ramp of 4 frames: scale 0.25, 0.5, 0.75, 1, 1 of the commanded 2 N.
        var shaper = new ForceShaper(maxForceN: 3, rampFrames: 4, staleFrames: 100);
        var command = new ServoCommand(0, 2, 0, true, 1);
        double[] expected = [0.5, 1.0, 1.5, 2.0, 2.0];
        foreach (var y in expected)
        {
            Assert.Equal((0.0, y, 0.0), Next(shaper, command));
        }

        Assert.Equal(1.0, shaper.Scale);
    }

    [Fact]
    public void An_over_limit_force_is_scaled_down_to_the_limit_keeping_its_direction()
    {
        // |(3, 4, 0)| = 5 N over a 2.5 N limit: halved to (1.5, 2, 0). No ramp: full scale on the first frame.
        var shaper = new ForceShaper(maxForceN: 2.5, rampFrames: 0, staleFrames: 100);

        Assert.Equal((1.5, 2.0, 0.0), Next(shaper, new ServoCommand(3, 4, 0, true, 1)));
        Assert.Equal((-1.5, 0.0, -2.0), Next(shaper, new ServoCommand(-3, 0, -4, true, 2)));
        Assert.Equal((0.5, -1.0, 2.0), Next(shaper, new ServoCommand(0.5, -1, 2, true, 3))); // |F| = 2.29 N: passed as is
    }

    [Fact]
    public void A_command_that_stops_changing_goes_stale_after_the_stale_frames_and_ramps_in_again_after()
    {
        // Stale after 3 frames: the frames that see sequence 1 at age 0, 1, 2 push; age 3 does not.
        var shaper = new ForceShaper(maxForceN: 10, rampFrames: 0, staleFrames: 3);
        var command = new ServoCommand(1, 0, 0, true, 1);
        Assert.Equal((1.0, 0.0, 0.0), Next(shaper, command));
        Assert.Equal((1.0, 0.0, 0.0), Next(shaper, command));
        Assert.Equal((1.0, 0.0, 0.0), Next(shaper, command));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, command));
        Assert.Equal(0.0, shaper.Scale);

        var ramped = new ForceShaper(maxForceN: 10, rampFrames: 2, staleFrames: 1);
        Assert.Equal((0.5, 0.0, 0.0), Next(ramped, command)); // age 0 < 1
        Assert.Equal((0.0, 0.0, 0.0), Next(ramped, command)); // age 1: stale
        Assert.Equal((0.5, 0.0, 0.0), Next(ramped, command with { Sequence = 2 })); // fresh again: the ramp restarts from zero
        Assert.Equal(0.5, ramped.Scale);
    }

    [Fact]
    public void Frames_without_a_command_age_it_too()
    {
        var shaper = new ForceShaper(maxForceN: 10, rampFrames: 0, staleFrames: 2);
        var command = new ServoCommand(0, 0, 1, true, 7);
        Assert.Equal((0.0, 0.0, 1.0), Next(shaper, command));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, command, haveCommand: false)); // no command this frame: nothing pushed
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, command)); // age 2 by now: stale
    }

    [Fact]
    public void Sequence_zero_disabled_and_non_finite_commands_push_nothing_and_reset_the_ramp()
    {
        var shaper = new ForceShaper(maxForceN: 10, rampFrames: 2, staleFrames: 100);
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, new ServoCommand(1, 1, 1, true, 0))); // sequence 0: nothing sent yet
        Assert.Equal(0.0, shaper.Scale);

        Assert.Equal((0.5, 0.0, 0.0), Next(shaper, new ServoCommand(1, 0, 0, true, 1)));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, new ServoCommand(1, 0, 0, false, 2))); // force disabled
        Assert.Equal(0.0, shaper.Scale);

        Assert.Equal((0.5, 0.0, 0.0), Next(shaper, new ServoCommand(1, 0, 0, true, 3)));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, new ServoCommand(double.NaN, 0, 0, true, 4)));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, new ServoCommand(0, double.PositiveInfinity, 0, true, 5)));
        Assert.Equal((0.0, 0.0, 0.0), Next(shaper, new ServoCommand(0, 0, double.NegativeInfinity, true, 6)));
        Assert.Equal(0.0, shaper.Scale);
        Assert.Equal((0.5, 0.0, 0.0), Next(shaper, new ServoCommand(1, 0, 0, true, 7))); // the ramp starts over
    }

    [Fact]
    public void Impossible_shaping_settings_are_refused()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => new ForceShaper(-0.1, 0, 1));
        Assert.Throws<ArgumentOutOfRangeException>(() => new ForceShaper(1, -1, 1));
        Assert.Throws<ArgumentOutOfRangeException>(() => new ForceShaper(1, 0, 0));
        Assert.Equal(0.0, new ForceShaper(0, 0, 1).Scale); // the smallest valid settings
    }
}
