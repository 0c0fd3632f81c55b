using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Touch.Backends;
using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Plugins.Touch.Tests.Simulation;

public sealed class SimulatedTouchBackendTests
{
    private static readonly TouchForce None = new(0, 0, 0);

    // x = 4 mm/s * t from 7 mm over two seconds (7 mm at 0 s, 15 mm at 2 s), yaw 0.2 rad throughout.
    private static HandScript Script() => HandScript.Parse(
        ["time_s,x_mm,y_mm,z_mm,yaw_rad", "0,7,1,2,0.2", "2,15,1,2,0.2"],
        "s.csv");

    private static SimulatedTouchBackend Backend(double maxForceN = 3.3, double offset = 0, bool repeat = false)
    {
        var backend = new SimulatedTouchBackend(Script(), new HandModel(0.25, 0.2, 0.01), maxForceN, offset, repeat);
        backend.Open();
        return backend;
    }

    [Fact]
    public void The_script_and_the_hand_are_required_by_name()
    {
        Assert.Equal("script", Assert.Throws<ArgumentNullException>(() => new SimulatedTouchBackend(null!, new HandModel(0.25, 0.2, 0.01), 3.3)).ParamName);
        Assert.Equal("hand", Assert.Throws<ArgumentNullException>(() => new SimulatedTouchBackend(Script(), null!, 3.3)).ParamName);
    }

    [Fact]
    public void The_first_reading_is_the_handle_at_rest_at_the_scripted_hand()
    {
        var sample = Backend().Exchange(0.5, None);

        Assert.Equal(new TouchSample(9, 1, 2, 0, 0, 0.2, false, false), sample);
    }

    [Fact]
    public void Reopening_puts_the_handle_back_at_the_hand()
    {
        var backend = Backend();
        backend.Exchange(0, None);
        backend.Exchange(0.1, new TouchForce(3, 0, 0)); // pushed away from the hand

        backend.Open();
        var sample = backend.Exchange(0.2, new TouchForce(3, 0, 0));

        Assert.Equal(7.8, sample.XMm, 12);
        Assert.Equal([7.8, 1, 2], backend.Hand.Position.ToArray());
    }

    [Fact]
    public void The_time_offset_starts_the_script_later()
    {
        Assert.Equal(9.0, Backend(offset: 0.5).Exchange(0, None).XMm, 12);
        Assert.Equal(13.0, Backend(offset: 0.5).Exchange(1, None).XMm, 12);
    }

    [Theory]
    [InlineData(false, 2.5, 15.0)] // after the end: the last keyframe
    [InlineData(true, 2.5, 9.0)] // 2.5 s is 0.5 s into the second pass
    [InlineData(true, 2.0, 15.0)] // the end itself is the end, not the start of the next pass
    [InlineData(true, 5.0, 11.0)] // third pass, 1 s in
    public void Repeat_starts_the_script_again_after_its_end(bool repeat, double t, double x) =>
        Assert.Equal(x, Backend(repeat: repeat).Exchange(t, None).XMm, 12);

    [Fact]
    public void A_jump_adds_to_every_later_reading_along_x()
    {
        var backend = Backend();
        Assert.Equal(7.0, backend.Exchange(0, None).XMm, 12);

        backend.Jump(2);
        backend.Jump(3);

        var sample = backend.Exchange(0.001, None);
        Assert.Equal(backend.Hand.Position[0] + 5, sample.XMm, 12);
        Assert.InRange(sample.XMm, 11.9, 12.1);
    }

    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    public void A_jump_must_be_finite(double jump)
    {
        var backend = Backend();

        Assert.Throws<ArgumentOutOfRangeException>(() => backend.Jump(jump));
        Assert.Equal(7.0, backend.Exchange(0, None).XMm, 12);
    }

    [Fact]
    public void A_frozen_device_repeats_its_last_reading_growing_older()
    {
        var backend = Backend();
        backend.Exchange(0, None);
        var last = backend.Exchange(0.25, new TouchForce(1, 0, 0));
        Assert.Equal((1.0, 0.0, 0.0), backend.LastRenderedForce);

        backend.Freeze();
        backend.Freeze(); // a second freeze does not restart the age
        var frozen = backend.Exchange(0.75, new TouchForce(1, 1, 1));
        var later = backend.Exchange(1.0, new TouchForce(1, 1, 1));

        Assert.Equal(last with { AgeMs = 500 }, frozen with { AgeMs = Math.Round(frozen.AgeMs, 9) });
        Assert.Equal(750, later.AgeMs, 9);
        Assert.Equal((0.0, 0.0, 0.0), backend.LastRenderedForce);
    }

    [Fact]
    public void A_device_frozen_before_its_first_reading_ages_from_time_zero()
    {
        var backend = Backend();
        backend.Freeze();

        var sample = backend.Exchange(0.2, None);

        Assert.Equal(new TouchSample(0, 0, 0, 0, 0, 0, false, false, 200), sample with { AgeMs = Math.Round(sample.AgeMs, 9) });
    }

    [Fact]
    public void A_force_over_the_maximum_is_scaled_to_the_maximum_along_its_direction()
    {
        // (2, 6, 3) N is 7 N long; at most 3.5 N: half of it, (1, 3, 1.5) N.
        var backend = Backend(maxForceN: 3.5);
        backend.Exchange(0, None);

        backend.Exchange(0.001, new TouchForce(2, 6, 3));
        var (x, y, z) = backend.LastRenderedForce;

        Assert.Equal(1.0, x, 12);
        Assert.Equal(3.0, y, 12);
        Assert.Equal(1.5, z, 12);
    }

    [Fact]
    public void A_force_within_the_maximum_passes_unchanged()
    {
        var backend = Backend(maxForceN: 3.5);
        backend.Exchange(0, None);

        backend.Exchange(0.001, new TouchForce(-1, 2, 2)); // 3 N long

        Assert.Equal((-1.0, 2.0, 2.0), backend.LastRenderedForce);
    }

    [Fact]
    public void The_description_names_the_scripts_keyframes_and_length()
    {
        Assert.Equal("simulated Touch (2 keyframes, 2 s)", Backend().Description);
    }

    [Fact]
    public void Settings_make_a_backend_from_the_script_file_with_their_offset_repeat_and_hand()
    {
        var dir = Directory.CreateTempSubdirectory("simtouch");
        try
        {
            File.WriteAllLines(Path.Combine(dir.FullName, "hand.csv"), ["time_s,x_mm,y_mm,z_mm", "0,7,1,2", "2,15,1,2"]);
            var settings = new TouchSettings { Script = "hand.csv", TimeOffsetS = 0.5, Repeat = true, HandMassKg = 0.5, MaxForceN = 2 };
            var context = new PluginContext("touch", null, TimeProvider.System, dir.FullName);

            var backend = SimulatedTouchBackend.Create(settings, context);
            backend.Open();

            Assert.Equal("simulated Touch (2 keyframes, 2 s)", backend.Description);
            Assert.Equal(9.0, backend.Exchange(2, None).XMm, 12); // 2.5 s into a 2 s script, repeated: 0.5 s
            backend.Exchange(2.00025, new TouchForce(4, 0, 0));
            Assert.Equal((2.0, 0.0, 0.0), backend.LastRenderedForce);

            // One 0.25 ms sub-step of 2 N on 0.5 kg, the hand moving at 4 mm/s (damping 0.01 N s/mm):
            // a = (2 + 0.01 * 4 + 0.2 * (hand moved 0.001 mm)) N / 0.5 kg = (2.0402 N) / 0.5 kg = 4080.4 mm/s².
            Assert.Equal(4080.4 * 0.00025, backend.Hand.Velocity[0], 9);
        }
        finally
        {
            dir.Delete(true);
        }
    }
}
