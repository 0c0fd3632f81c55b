using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>The pot reading and the encoder position it is compared with come from one instant (the pot poll's).</summary>
public sealed class PotSampleTests
{
    [Fact]
    public void The_encoder_position_kept_with_a_pot_reading_is_the_one_published_when_the_pot_was_read()
    {
        using var lb = new VirtualLb();
        var motor = lb.Robot.Motors[0];
        Assert.True(double.IsNaN(motor.PositionAtPotRad)); // no pot read yet
        const int raw = 2000; // an ADC reading inside every shipped pot curve

        motor.Publish(0.25, 0, 0);
        motor.PublishPot(raw);
        Assert.Equal(0.25, motor.PositionAtPotRad);
        var pot = motor.PotPositionRad;

        motor.Publish(0.40, 0, 0); // the joint moves on; the pot is read again only at the next pot poll
        Assert.Equal(0.25, motor.PositionAtPotRad);
        Assert.Equal(pot, motor.PotPositionRad);
        Assert.Equal(0.40, motor.PositionRad);
    }
}
