using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

/// <summary>Homing from the joint pots through the firmware's home_request, on modules that already have a position record.</summary>
public sealed class HomingTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Home_replaces_a_stale_resumed_position_with_the_pot_position()
    {
        using var lb = new VirtualLb();
        var elbow = lb.Sim.Axis(0, "elbow");
        var elbowMotor = lb.Robot.Motor("right.elbow");

        // Move the elbow under control: the module's position record now holds the moved position.
        lb.Robot.WriteJointSetpoints(0, [0.0, 0.0, 0.0, 80 * Deg, 60 * Deg]);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(1200));
        Assert.InRange(elbow.OutputAngleRad - (80 * Deg), -1 * Deg, 1 * Deg);
        lb.Robot.EnableTorque(false);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(20));
        Span<double> before = stackalloc double[5];
        lb.Robot.ReadJointPositions(0, before);

        // The elbow is turned by hand while its module is off: the module resumes its saved, now wrong, position.
        var moved = elbow.OutputAngleRad;
        const double turn = 25 * Deg;
        lb.Sim.TurnWhileOff(elbow, moved + turn);
        lb.Sim.Advance(TimeSpan.FromMilliseconds(2));
        var stale = elbowMotor.Config.ToRadians(lb.Robot.ReadParameter(2, "present_position"));
        Assert.InRange(stale - moved, -0.5 * Deg, 0.5 * Deg);
        Assert.True(((HardwareErrors)lb.Robot.ReadParameter(2, "motor_error")).HasFlag(HardwareErrors.PotMismatch));

        var results = lb.Robot.Home();

        Assert.Equal(lb.Robot.Motors.Count, results.Count);
        Assert.All(results, r => Assert.True(r.Succeeded, r.ToString()));
        var home = results.Single(r => r.Motor == elbowMotor);
        Assert.Equal(HardwareErrors.None, home.MotorErrors);
        // The pot's non-linearity is modelled by the calibration points; what remains is calibration error and noise.
        Assert.InRange(home.PositionRad - elbow.OutputAngleRad, -0.5 * Deg, 0.5 * Deg);
        Assert.InRange(home.ErrorRad, -0.2 * Deg, 0.2 * Deg);
        Assert.InRange(elbowMotor.PositionRad - elbow.OutputAngleRad, -0.5 * Deg, 0.5 * Deg);
        Assert.Equal(HardwareErrors.None, (HardwareErrors)lb.Robot.ReadParameter(2, "hardware_error_status") & (HardwareErrors.PotMismatch | HardwareErrors.PositionLost));

        // The joints read the pot-derived position: only the joints the elbow actuator drives moved.
        Span<double> q = stackalloc double[5];
        lb.Robot.ReadJointPositions(0, q);
        var k = lb.Robot.Map.IndexOfActuator("elbow");
        for (var j = 0; j < 5; j++)
        {
            var expected = before[j] + (lb.Robot.Map.InverseCoefficient(j, k) * turn);
            Assert.InRange(q[j] - expected, -0.5 * Deg, 0.5 * Deg);
        }

        // The homed position was saved: a power cycle keeps it, and the pot agrees.
        lb.Sim.PowerCycle(2);
        lb.Sim.Advance(TimeSpan.FromMilliseconds(2));
        Assert.InRange(elbowMotor.Config.ToRadians(lb.Robot.ReadParameter(2, "present_position")) - home.PositionRad, -0.01 * Deg, 0.01 * Deg);
        Assert.Equal(HardwareErrors.None, (HardwareErrors)lb.Robot.ReadParameter(2, "hardware_error_status") & HardwareErrors.PotMismatch);

        // Turning the motors on again holds them where they are: goal and setpoint moved with the position.
        lb.Robot.EnableTorque(true);
        lb.Robot.RunFor(TimeSpan.FromMilliseconds(500));
        Assert.InRange(elbow.OutputAngleRad - (moved + turn), -0.5 * Deg, 0.5 * Deg);
    }

    [Fact]
    public void Home_needs_the_motors_off_and_reports_a_module_that_refuses()
    {
        using var lb = new VirtualLb();
        var error = Assert.Throws<InvalidOperationException>(() => lb.Robot.Home());
        Assert.Contains("EnableTorque(false)", error.Message, StringComparison.Ordinal);

        lb.Robot.EnableTorque(false);
        // Module 2 is driven behind the robot layer's back: the firmware refuses to re-home it, the others are homed.
        Assert.True(lb.Robot.Client.Write(2, ControlTable.Firmware["torque_enable"].At(0), [1]).Succeeded);
        var position = lb.Robot.ReadParameter(2, "present_position");

        var results = lb.Robot.Home();

        var refused = Assert.Single(results, r => r.Motor.Controller.Id == 2);
        Assert.Equal(HomingOutcome.Refused, refused.Outcome);
        Assert.Contains("torque", refused.Detail, StringComparison.Ordinal);
        Assert.Contains("REFUSED", refused.ToString(), StringComparison.Ordinal);
        Assert.Equal(position, lb.Robot.ReadParameter(2, "present_position"));
        Assert.All(results.Where(r => r.Motor.Controller.Id != 2), r => Assert.Equal(HomingOutcome.Homed, r.Outcome));
    }

    [Fact]
    public void Motors_without_a_pot_calibration_are_reported_not_homed()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { Commissioned = false }, start: false);
        lb.Robot.Discover();

        var results = lb.Robot.Home();

        Assert.Equal(lb.Robot.Motors.Count, results.Count);
        foreach (var r in results)
        {
            Assert.Equal(HomingOutcome.NotCalibrated, r.Outcome);
            Assert.False(r.Succeeded);
            Assert.True(double.IsNaN(r.PotPositionRad));
            Assert.False(double.IsNaN(r.PositionRad));
            Assert.Contains("pot_cal_count", r.Detail, StringComparison.Ordinal);
        }
    }
}
