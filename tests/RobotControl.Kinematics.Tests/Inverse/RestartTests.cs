using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Kinematics.Tests.Inverse;

/// <summary>The solver's restarts: hops along a singular pose's free direction, and the fixed seeds nearest the target.</summary>
public sealed class RestartTests
{
    private const double Deg = Math.PI / 180;

    [Theory]
    [InlineData(new[] { -30.0, -20, 40, 0, 70 })]   // elbow straight: shoulder roll and tool roll on one line
    [InlineData(new[] { -40.0, -90, 20, 60, -10 })] // pitch at -90°: yaw and shoulder roll on one line
    public void Hops_from_a_singular_pose_keep_the_tool_where_it_is_and_move_the_aligned_joints(double[] deg)
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var q = deg.Select(d => d * Deg).ToArray();
        var state = chain.CreateState();
        state.Update(q);
        var pose = state.ToolPose;
        var hops = new AlignedAxisHops(chain, chain.MinRad.ToArray(), chain.MaxRad.ToArray());

        var count = hops.Propose(state, q);

        Assert.InRange(count, 1, AlignedAxisHops.MaxHops);
        var hop = new double[chain.JointCount];
        for (var k = 0; k < count; k++)
        {
            Assert.True(hops.Any);
            hops.Next(hop);
            Assert.True(chain.WithinLimits(hop), $"hop {k} outside limits");
            var moved = Enumerable.Range(0, q.Length).Where(i => Math.Abs(hop[i] - q[i]) > 1e-9).ToList();
            Assert.Equal(2, moved.Count);
            state.Update(hop);
            Assert.True((state.ToolPosition - pose.Position).Length < 1e-9, $"hop {k} moved the tool by {(state.ToolPosition - pose.Position).Length} mm");
            for (var c = 0; c < 3; c++)
            {
                Assert.True(IkTestData.Angle(state.ToolRotation[c], pose.Rotation[c]) < 1e-9, $"hop {k} turned axis {c}");
            }
        }

        Assert.False(hops.Any);
    }

    [Fact]
    public void A_pose_with_no_two_axes_on_one_line_proposes_no_hop()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var q = new[] { -30 * Deg, -20 * Deg, 40 * Deg, 60 * Deg, 70 * Deg };
        var state = chain.CreateState();
        state.Update(q);

        var hops = new AlignedAxisHops(chain, chain.MinRad.ToArray(), chain.MaxRad.ToArray());

        Assert.Equal(0, hops.Propose(state, q));
        Assert.False(hops.Any);
    }

    [Fact]
    public void Restart_seeds_come_nearest_first_each_once_and_within_the_limits_and_none_nearer_is_left_out()
    {
        var chain = new KinematicChain(TestRobots.Lb);
        var options = new IkOptions();
        var problem = new IkProblem(chain, options);
        Assert.True(problem.SetTarget(IkTestData.TargetOf(chain, [-0.4, -0.7, 0.3, 1.1, 2.0], OrientationAxes.All)));
        var seeds = new RestartSeeds(chain, chain.MinRad, chain.MaxRad);
        var again = new RestartSeeds(chain, chain.MinRad, chain.MaxRad);
        seeds.Rank(problem);
        again.Rank(problem);

        var q = new double[chain.JointCount];
        var same = new double[chain.JointCount];
        var taken = new HashSet<string>();
        var previous = 0.0;
        for (var s = 0; s < RestartSeeds.Kept; s++)
        {
            seeds.Next(q);
            again.Next(same);
            Assert.Equal(q, same); // deterministic
            Assert.True(chain.WithinLimits(q));
            Assert.True(taken.Add(string.Join(",", q)), $"seed {s} given twice");
            var cost = problem.Evaluate(q);
            Assert.True(cost >= previous - 1e-9, $"seed {s} costs {cost}, less than the one before ({previous})");
            previous = cost;
        }

        // No seed of the whole set that was not handed out is nearer than the last one that was.
        var all = new RestartSeeds(chain, chain.MinRad, chain.MaxRad);
        var nearerLeftOut = 0;
        for (var s = 0; s < RestartSeeds.Count; s++)
        {
            all.SeedAt(s, q);
            if (!taken.Contains(string.Join(",", q)) && problem.Evaluate(q) < previous - 1e-9)
            {
                nearerLeftOut++;
            }
        }

        Assert.Equal(0, nearerLeftOut);
    }
}
