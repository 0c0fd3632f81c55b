using System.Text.Json.Nodes;
using RobotControl.Definitions.Loading;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Control;
using RobotControl.Simulation;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus;

public sealed class BusRobotTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Discovery_finds_every_configured_module_with_its_motors_named_after_joints()
    {
        using var lb = new VirtualLb();
        Assert.True(lb.Discovery!.AllAsConfigured, string.Join("\n", lb.Discovery.Lines()));
        Assert.Equal(6, lb.Discovery.Present.Count);
        var shoulder = lb.Robot.Controller(1)!;
        Assert.Equal("right shoulder", shoulder.Name);
        Assert.Equal(["shoulder_yaw", "shoulder_pitch", "shoulder_roll"], shoulder.Motors.Select(m => m.Name));
        Assert.Equal("left.tool_open_close", lb.Robot.Controller(13)!.Motors[1].Config.FullName);
        Assert.Equal(RobotFaults.None, lb.Robot.Faults);
    }

    [Fact]
    public void Missing_and_unknown_modules_are_reported()
    {
        using var lb = new VirtualLb(hostView: VirtualLb.MisconfiguredHostView());
        var report = lb.Discovery!;
        Assert.Equal([20], report.Missing.Select(c => (int)c.Id));
        Assert.Equal([3, 13], report.Unknown.Select(p => (int)p.Id).Order());
        Assert.Contains(report.Lines(), l => l.StartsWith("MISSING  id  20", StringComparison.Ordinal));
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.ModuleMissing));
    }

    [Fact]
    public void Parameters_round_trip_through_FRAM_across_a_power_cycle()
    {
        using var lb = new VirtualLb();
        Assert.Empty(lb.Robot.CheckParameters());

        var kp = lb.Robot.ReadParameter(2, "kp", 0);

        // The persistent area is locked while a motor is driven (access error), as Dynamixel locks its EEPROM area.
        var locked = Assert.Throws<IOException>(() => lb.Robot.WriteParameter(2, "kp", 0, kp + 7));
        Assert.Contains("0x07 access error", locked.Message, StringComparison.Ordinal);
        Assert.Contains("torque", locked.Message, StringComparison.Ordinal);
        Assert.Equal(kp, lb.Robot.ReadParameter(2, "kp", 0));
        lb.Robot.EnableTorque(false);

        // The rules refuse before the bus (the firmware itself would take a position_min above position_max).
        var max = lb.Robot.ReadParameter(2, "position_max", 0);
        var refused = Assert.Throws<ArgumentException>(() => lb.Robot.WriteParameter(2, "position_min", 0, max + 1));
        Assert.Equal($"module 2: motor 0: position_min {max + 1} must be below position_max {max}; nothing was written", refused.Message);
        Assert.True(lb.Robot.ReadParameter(2, "position_min", 0) < max);
        Assert.Equal(kp + 7, lb.Robot.WriteParameter(2, "kp", 0, kp + 7));
        lb.Sim.PowerCycle(2);
        lb.Sim.Advance(TimeSpan.FromMilliseconds(2));
        Assert.Equal(kp + 7, lb.Robot.ReadParameter(2, "kp", 0));

        var mismatch = Assert.Single(lb.Robot.CheckParameters());
        Assert.Equal("kp", mismatch.Expected.Field.Name);
        Assert.Equal(kp + 7, mismatch.Actual);
        lb.Robot.WriteParameters();
        Assert.Empty(lb.Robot.CheckParameters());
    }

    [Fact]
    public void Uncommissioned_modules_disagree_with_the_robot_file()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { Commissioned = false }, start: false);
        lb.Robot.Discover();
        var mismatches = lb.Robot.CheckParameters();
        Assert.Contains(mismatches, m => m.ModuleId == 1 && m.Expected.Field.Name == "kp");
        Assert.Contains(mismatches, m => m.ModuleId == 13 && m.Expected.Field.Name == "pot_cal_count");
    }

    [Fact]
    public void Homing_takes_each_position_from_its_non_linear_pot()
    {
        var right = new[] { -30 * Deg, 20 * Deg, 40 * Deg, 100 * Deg, -120 * Deg };
        var left = new[] { 10 * Deg, -60 * Deg, -70 * Deg, 30 * Deg, 150 * Deg };
        using var lb = new VirtualLb(new VirtualRobotOptions { InitialJointsRad = [right, left], InitialJawRad = 20 * Deg }, start: false);
        lb.Robot.Discover();
        var results = lb.Robot.Home();
        Assert.Equal(12, results.Count);
        foreach (var r in results)
        {
            Assert.Equal(HomingOutcome.Homed, r.Outcome);
            var truth = lb.Sim.Axes.Single(a => a.Config.FullName == r.Motor.Config.FullName).OutputAngleRad;
            Assert.InRange(r.PositionRad - truth, -0.5 * Deg, 0.5 * Deg);
            Assert.InRange(r.ErrorRad, -0.5 * Deg, 0.5 * Deg);
        }

        Span<double> q = stackalloc double[5];
        lb.Robot.ReadJointPositions(1, q);
        for (var j = 0; j < 5; j++)
        {
            Assert.InRange(q[j] - left[j], -0.5 * Deg, 0.5 * Deg);
        }
    }

    [Fact]
    public void A_joint_move_settles_at_the_setpoint()
    {
        using var lb = new VirtualLb();
        var target = new[] { -20 * Deg, 10 * Deg, 30 * Deg, 90 * Deg, 45 * Deg };
        lb.Robot.WriteJointSetpoints(0, target);
        lb.Robot.WriteJawSetpoint(0, 40 * Deg);
        lb.Robot.RunFor(TimeSpan.FromSeconds(1.5));

        Span<double> q = stackalloc double[5];
        lb.Robot.ReadJointPositions(0, q);
        for (var j = 0; j < 5; j++)
        {
            Assert.InRange(q[j] - target[j], -0.5 * Deg, 0.5 * Deg);
        }

        foreach (var axis in lb.Sim.Axes.Where(a => a.Config.Arm == 0 && a.Config.Actuator.IsKinematic))
        {
            var k = lb.Robot.Map.IndexOfActuator(axis.Config.Actuator.Name);
            var expected = Enumerable.Range(0, 5).Sum(j => lb.Robot.Map.Coefficient(k, j) * target[j]);
            Assert.InRange(axis.OutputAngleRad - expected, -1.5 * Deg, 1.5 * Deg); // backlash and one Hall count
        }

        Assert.InRange(lb.Robot.Motor("right.tool_open_close").PositionRad - (40 * Deg), -0.5 * Deg, 0.5 * Deg);
        Assert.True(RobotFaults.None == (lb.Robot.Faults & ~RobotFaults.CurrentLimited), string.Join("\n", lb.Robot.Events));
    }

    [Fact]
    public void Joint_limits_and_non_finite_values_never_reach_a_motor()
    {
        using var lb = new VirtualLb();
        lb.Robot.WriteJointSetpoints(0, [0, 0, 0, 200 * Deg, double.NaN]);
        lb.Robot.RunFor(TimeSpan.FromSeconds(2.5));
        Span<double> q = stackalloc double[5];
        lb.Robot.ReadJointPositions(0, q);
        Assert.InRange(q[3], 149 * Deg, 150.5 * Deg);
        Assert.True(lb.Robot.Faults.HasFlag(RobotFaults.SetpointRejected));
    }
}
