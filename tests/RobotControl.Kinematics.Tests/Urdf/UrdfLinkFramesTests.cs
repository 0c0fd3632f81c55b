using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Mirroring;
using RobotControl.Kinematics.Urdf;

namespace RobotControl.Kinematics.Tests.Urdf;

/// <summary>The link frames a recording puts on <c>/tf</c>: composed from the root to each tool, they give the project's forward kinematics, mirrored arm included.</summary>
public sealed class UrdfLinkFramesTests
{
    [Theory]
    [MemberData(nameof(TestRobots.Names), MemberType = typeof(TestRobots))]
    public void The_frames_from_the_root_to_a_tool_compose_to_the_tool_pose(string file)
    {
        var robot = TestRobots.ByFile(file);
        var frames = new UrdfLinkFrames(robot);
        var chain = new KinematicChain(robot);
        var state = chain.CreateState();
        var random = new Random(21);
        var q = new double[chain.JointCount];
        for (var sample = 0; sample < 50; sample++)
        {
            TestRobots.FillRandomJoints(chain, random, q);
            state.Update(q);
            foreach (var arm in robot.Arms)
            {
                var (position, rotation) = Compose(frames, UrdfExport.ToolLinkName(arm.Name), q);
                var expected = new ArmMirror(robot, arm.Name).ModelToBody(state.ToolPose);
                Assert.True((expected.Position - position).Length < 1e-9, $"{arm.Name}: {position} against {expected.Position}");
                for (var c = 0; c < 3; c++)
                {
                    Assert.True((expected.Rotation[c] - rotation[c]).Length < 1e-12, $"{arm.Name}: rotation column {c}");
                }
            }
        }

        Assert.All(Enumerable.Range(0, frames.Count), i => Assert.Equal(robot.Arms[frames.Arm(i)].Name, frames.Child(i).Split('_')[0]));
    }

    /// <summary>The child link <paramref name="link"/> in the root, walking the parents.</summary>
    private static (Vector3d Position, Rotation3d Rotation) Compose(UrdfLinkFrames frames, string link, double[] q)
    {
        var path = new List<int>();
        for (var current = link; Enumerable.Range(0, frames.Count).FirstOrDefault(i => frames.Child(i) == current, -1) is var i && i >= 0; current = frames.Parent(i))
        {
            path.Insert(0, i);
        }

        var position = Vector3d.Zero;
        var rotation = Rotation3d.Identity;
        foreach (var i in path)
        {
            var (p, r) = frames.Transform(i, q);
            position += rotation.Apply(p);
            rotation *= r;
        }

        return (position, rotation);
    }
}
