using RobotControl.Robot.Calibration;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Calibration;

/// <summary>
/// The LB-1.0's calibration sweeps: each motor reaches both ends of its range (less the margin), and no joint leaves
/// its limits at any way point. The joints are recovered from the motors by hand from the robot file's couplings
/// (shoulder_1 = yaw + pitch, shoulder_2 = yaw - pitch, shoulder_3 = roll - yaw - pitch, so yaw = (s1 + s2) / 2,
/// pitch = (s1 - s2) / 2, roll = s3 + s1), not through the map the plan uses.
/// </summary>
public sealed class PotSweepPlanTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void The_shoulders_sweeps_reach_each_motors_ends_through_corners_of_the_joint_box_without_leaving_it()
    {
        var lb = VirtualLb.Lb;
        var plan = new PotSweepPlan(lb, lb.Modules.Modules.Single(m => m.Name == "right shoulder"));
        Assert.Equal(new[] { "right.shoulder_yaw", "right.shoulder_pitch", "right.shoulder_roll" }, plan.Motors.Select(m => m.FullName));
        var joint = lb.Joints.ToDictionary(j => j.Name);
        AssertJointsAt(plan.Reference, joint["shoulder_yaw"].MidRad, joint["shoulder_pitch"].MidRad, joint["shoulder_roll"].MidRad);
        for (var i = 0; i < plan.Motors.Count; i++)
        {
            var sweep = plan.Sweep(i);
            Assert.Equal(4, sweep.Count);
            Assert.Equal(plan.Reference, sweep[0]);
            Assert.Equal(plan.Reference, sweep[^1]);
            var m = plan.Motors[i];
            var margin = (i == 2 ? 3 : 2) * PotSweepPlan.MarginRad; // the motor's |coupling coefficients| summed
            Assert.Equal(m.OutputMinRad + margin, sweep[1][i], 9);
            Assert.Equal(m.OutputMaxRad - margin, sweep[2][i], 9);
            foreach (var point in sweep)
            {
                var (yaw, pitch, roll) = ((point[0] + point[1]) / 2, (point[0] - point[1]) / 2, point[2] + point[0]);
                Assert.InRange(yaw, joint["shoulder_yaw"].MinRad, joint["shoulder_yaw"].MaxRad);
                Assert.InRange(pitch, joint["shoulder_pitch"].MinRad, joint["shoulder_pitch"].MaxRad);
                Assert.InRange(roll, joint["shoulder_roll"].MinRad, joint["shoulder_roll"].MaxRad);
            }
        }

        // The roll motor's low end: roll at its minimum, yaw and pitch at their maxima (s3 = -90 - 45 - 45 deg + margins).
        Assert.Equal((-180 * Deg) + (3 * PotSweepPlan.MarginRad), plan.Sweep(2)[1][2], 9);
    }

    [Fact]
    public void The_jaw_drive_sweeps_its_own_range_with_the_tool_roll_held_at_the_fixture_pose()
    {
        var lb = VirtualLb.Lb;
        var plan = new PotSweepPlan(lb, lb.Modules.Modules.Single(m => m.Name == "left forearm"));
        var jaw = plan.Motors.ToList().FindIndex(m => m.Name == "tool_open_close");
        var roll = 1 - jaw;
        var sweep = plan.Sweep(jaw);
        Assert.Equal(30 * Deg, plan.Reference[jaw], 9);
        Assert.Equal(lb.Tool.JawMinRad + PotSweepPlan.MarginRad, sweep[1][jaw], 9);
        Assert.Equal(lb.Tool.JawMaxRad - PotSweepPlan.MarginRad, sweep[2][jaw], 9);
        Assert.All(sweep, p => Assert.Equal(plan.Reference[roll], p[roll], 9));
        Assert.Equal((-180 * Deg) + PotSweepPlan.MarginRad, plan.Sweep(roll)[1][roll], 9);
    }

    private static void AssertJointsAt(IReadOnlyList<double> shoulder, double yaw, double pitch, double roll)
    {
        Assert.Equal(yaw + pitch, shoulder[0], 9);
        Assert.Equal(yaw - pitch, shoulder[1], 9);
        Assert.Equal(roll - yaw - pitch, shoulder[2], 9);
    }
}
