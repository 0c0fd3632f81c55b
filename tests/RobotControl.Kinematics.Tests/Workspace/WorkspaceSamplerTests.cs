using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Mirroring;
using RobotControl.Kinematics.Workspace;

namespace RobotControl.Kinematics.Tests.Workspace;

public sealed class WorkspaceSamplerTests
{
    [Fact]
    public void Every_point_is_a_tool_position_the_arm_reaches_within_its_limits()
    {
        var robot = TestRobots.Lb;
        var arms = WorkspaceSampler.Sample(robot, 2000, 1000);
        Assert.Equal(robot.Arms.Select(a => a.Name), arms.Select(a => a.Arm));
        var reach = robot.Dh.Sum(r => Math.Abs(r.AMm) + Math.Abs(r.DMm));
        foreach (var arm in arms)
        {
            var mirror = new ArmMirror(robot, arm.Arm);
            Assert.Equal(2000, arm.Interior.Count);
            Assert.Equal(1000, arm.Walls.Count);
            Assert.All(arm.Interior.Concat(arm.Walls), p => Assert.InRange(mirror.BodyToModel(p).Length, 0, reach + 1e-9));
        }

        // The cloud spans the arm's reach rather than a corner of it: its extent is a good part of the reach.
        var right = arms.Single(a => a.Arm == "right").Interior;
        var spread = right.Max(p => p.X) - right.Min(p => p.X);
        Assert.True(spread > 0.3 * reach, $"x spread {spread:F1} mm of reach {reach:F1} mm");
    }

    [Fact]
    public void The_mirrored_arm_samples_the_mirror_image_and_a_seed_repeats_the_draw()
    {
        var robot = TestRobots.Lb;
        var arms = WorkspaceSampler.Sample(robot, 300, 200, seed: 7);
        var again = WorkspaceSampler.Sample(robot, 300, 200, seed: 7);
        var right = arms.Single(a => a.Arm == "right");
        var left = arms.Single(a => a.Arm == "left");
        var rightMirror = new ArmMirror(robot, "right");
        var leftMirror = new ArmMirror(robot, "left");
        for (var i = 0; i < right.Interior.Count; i++)
        {
            Assert.True(Vector3d.Distance(rightMirror.BodyToModel(right.Interior[i]), leftMirror.BodyToModel(left.Interior[i])) < 1e-9);
            Assert.Equal(right.Interior[i], again.Single(a => a.Arm == "right").Interior[i]);
        }
    }
}
