using RobotControl.Plugins.Touch.Simulation;

namespace RobotControl.Plugins.Touch.Tests.Simulation;

public sealed class HandModelTests
{
    private static readonly double[] Origin = [0, 0, 0];

    [Theory]
    [InlineData(0, 0.2, 0.01)]
    [InlineData(-0.25, 0.2, 0.01)]
    [InlineData(0.25, 0, 0.01)]
    [InlineData(0.25, -0.2, 0.01)]
    [InlineData(0.25, 0.2, -0.001)]
    public void A_hand_needs_a_positive_mass_and_stiffness_and_a_non_negative_damping(double mass, double stiffness, double damping) =>
        Assert.Throws<ArgumentOutOfRangeException>(() => new HandModel(mass, stiffness, damping));

    [Fact]
    public void Reset_places_the_handle_at_rest_where_it_is_told()
    {
        var hand = new HandModel(0.25, 0.2, 0.01);
        hand.Step(0.01, Origin, Origin, 1, 2, 3); // now moving
        Assert.NotEqual(0.0, hand.Velocity[0]);

        hand.Reset([4, 5, 6, 0.1, 0.2, 0.3]); // a pose: only x, y, z are the handle's

        Assert.Equal([4.0, 5.0, 6.0], hand.Position.ToArray());
        Assert.Equal([0.0, 0.0, 0.0], hand.Velocity.ToArray());
    }

    [Fact]
    public void A_step_of_no_time_changes_nothing()
    {
        var hand = new HandModel(0.25, 0.2, 0.01);
        hand.Reset([1, 2, 3]);

        hand.Step(0, [10, 10, 10], [5, 5, 5], 1, 1, 1);

        Assert.Equal([1.0, 2.0, 3.0], hand.Position.ToArray());
        Assert.Equal([0.0, 0.0, 0.0], hand.Velocity.ToArray());
    }

    // m = 0.25 kg, k = 0.2 N/mm, b = 0, hand still at the handle at 0, 1 N along x, sub-steps h = 0.25 ms.
    // One: a = 1 N / 0.25 kg = 4 m/s² = 4000 mm/s²; v = 4000 * 0.00025 = 1 mm/s; x = 1 * 0.00025 = 0.00025 mm.
    // Two: spring 0.2 * -0.00025 = -0.00005 N, a = 0.99995 N / 0.25 kg = 3999.8 mm/s², v = 1 + 3999.8 * 0.00025
    // = 1.99995 mm/s, x = 0.00025 + 1.99995 * 0.00025 = 0.0007499875 mm.
    [Theory]
    [InlineData(0.00025, 1.0, 0.00025)]
    [InlineData(0.0005, 1.99995, 0.0007499875)]
    public void A_step_is_semi_implicit_euler_in_sub_steps_of_a_quarter_millisecond(double seconds, double velocity, double position)
    {
        var hand = new HandModel(0.25, 0.2, 0);
        hand.Reset(Origin);

        hand.Step(seconds, Origin, Origin, 1, 0, 0);

        Assert.Equal(velocity, hand.Velocity[0], 12);
        Assert.Equal(position, hand.Position[0], 15);
    }

    [Fact]
    public void A_long_step_is_the_same_time_in_small_steps()
    {
        var once = new HandModel(0.25, 0.2, 0.01);
        var small = new HandModel(0.25, 0.2, 0.01);
        once.Reset(Origin);
        small.Reset(Origin);
        double[] target = [10, -5, 2];
        double[] still = [0, 0, 0];

        once.Step(0.05, target, still, 0.5, 0, -0.5);
        for (var k = 0; k < 200; k++)
        {
            small.Step(0.00025, target, still, 0.5, 0, -0.5);
        }

        for (var k = 0; k < 3; k++)
        {
            Assert.Equal(small.Position[k], once.Position[k], 9);
            Assert.Equal(small.Velocity[k], once.Velocity[k], 9);
        }
    }

    [Fact]
    public void A_long_step_follows_the_undamped_spring()
    {
        // No damping, hand still at 0, 1 N: x(t) = F/k (1 - cos ω t), ω = sqrt(k / m) = sqrt(200 N/m / 0.25 kg)
        // = sqrt(800) rad/s. A quarter period, t = π / (2 sqrt 800) = 0.0555360 s: x = 5 mm, v = F/k ω = 141.42 mm/s.
        var hand = new HandModel(0.25, 0.2, 0);
        hand.Reset(Origin);

        hand.Step(0.0555360, Origin, Origin, 1, 0, 0);

        Assert.Equal(5.0, hand.Position[0], 1);
        Assert.Equal(141.42, hand.Velocity[0], 0);
    }
}
