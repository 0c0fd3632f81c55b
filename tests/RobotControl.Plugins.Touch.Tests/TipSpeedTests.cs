namespace RobotControl.Plugins.Touch.Tests;

/// <summary>The tip speed the Touch reports for the jump check: distance over the time between the readings' own instants.</summary>
public sealed class TipSpeedTests
{
    [Fact]
    public void The_speed_is_the_distance_over_the_time_between_readings_and_the_first_reading_gives_zero()
    {
        var speed = new TipSpeed();
        Assert.Equal(0, speed.Speed(1.000, 0, 0, 0));
        Assert.Equal(500, speed.Speed(1.002, 0.6, 0.8, 0), 9); // 1 mm in 2 ms
        Assert.Equal(0, speed.Speed(1.003, 0.6, 0.8, 0), 9);   // at rest
    }

    [Fact]
    public void A_reading_repeated_by_a_device_slower_than_the_loop_keeps_the_last_speed()
    {
        var speed = new TipSpeed();
        speed.Speed(1.000, 0, 0, 0);
        Assert.Equal(1000, speed.Speed(1.001, 1, 0, 0), 9);
        Assert.Equal(1000, speed.Speed(1.001, 1, 0, 0), 9); // same instant (tick time less the reading's age): same reading
    }

    [Fact]
    public void Two_readings_bunched_up_by_a_late_loop_are_taken_one_servo_period_apart_at_least()
    {
        var speed = new TipSpeed();
        speed.Speed(1.000, 0, 0, 0);
        // 1.5 mm of ordinary motion seen 0.05 ms apart would be 30 m/s; over the 1 ms floor it is 1.5 m/s.
        Assert.Equal(1500, speed.Speed(1.00005, 1.5, 0, 0), 9);
        Assert.Equal(TipSpeed.MinIntervalSeconds, 1e-3);
    }

    [Fact]
    public void A_non_finite_position_is_implausible()
    {
        var speed = new TipSpeed();
        speed.Speed(1.000, 0, 0, 0);
        Assert.True(double.IsNaN(speed.Speed(1.001, double.NaN, 0, 0)));
        Assert.Equal(1000, speed.Speed(1.002, 2, 0, 0), 9); // from the last finite reading, 2 ms before
    }
}
