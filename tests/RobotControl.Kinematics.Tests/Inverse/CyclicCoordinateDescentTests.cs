using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

public sealed class CyclicCoordinateDescentTests
{
    // BestStep maximises g(φ) = k1 (1 - cos φ) + k2 cos φ + k3 sin φ over q + φ in [min, max]: with a = k2 - k1 the
    // φ-dependent part is a cos φ + k3 sin φ, largest at φ = atan2(k3, a).
    [Fact]
    public void The_step_is_the_maximum_of_the_sinusoid_when_it_lies_in_range()
    {
        Assert.Equal(Math.PI / 2, CyclicCoordinateDescent.BestStep(0, 0, 1, 0, -Math.PI, Math.PI), 15);
        Assert.Equal(Math.PI / 4, CyclicCoordinateDescent.BestStep(1, 2, 1, 0.3, -Math.PI, Math.PI), 12);
    }

    [Fact]
    public void An_amplitude_at_the_noise_threshold_of_the_coefficients_gives_no_step()
    {
        // |a| + |k3| = 1 against 1e-12 (|k1| + |k2| + |k3|) = 1 + 1e-12: noise, the joint stays put. Just above it,
        // it turns by atan2(k3, a) = 90°.
        Assert.Equal(0, CyclicCoordinateDescent.BestStep(0.5e12, 0.5e12, 1, 0, -Math.PI, Math.PI));
        Assert.Equal(Math.PI / 2, CyclicCoordinateDescent.BestStep(0.5e12, 0.5e12, 1.001, 0, -Math.PI, Math.PI), 15);
    }
}
