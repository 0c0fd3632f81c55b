using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Kinematics;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Kinematics;

/// <summary>The IK plug-in's outputs checked with forward kinematics (a separate code path from the solver).</summary>
public sealed class InverseKinematicsPluginTests
{
    private static PluginDriver Ik(InverseKinematicsSettings settings) =>
        new(new InverseKinematicsPlugin(settings, PluginContext.Standalone("ik", ShippedRobots.Lb)));

    private static double[] Joints(PluginDriver ik, KinematicChain chain) =>
        [.. Enumerable.Range(0, chain.JointCount).Select(j => ik.Plugin.GetOutput(j))];

    [Fact]
    public void The_inputs_start_at_the_tool_position_of_the_initial_joints()
    {
        var chain = new KinematicChain(ShippedRobots.Lb);
        var state = chain.CreateState();
        state.Update([.. new[] { -30.0, -30, 0, 90, 0 }.Select(d => d * Math.PI / 180)]);
        var ik = Ik(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" });

        ik.Tick(); // no input set: the target is where the arm starts, so nothing moves

        Assert.Equal(1.0, ik["reached"]);
        var joints = Joints(ik, chain);
        Assert.Equal(-30 * Math.PI / 180, joints[0], 6);
        Assert.Equal(90 * Math.PI / 180, joints[3], 6);
        Assert.True(ik["error_mm"] < 0.01, $"error {ik["error_mm"]}");
        Assert.Equal(0.0, Vector3d.Distance(state.ToolPosition, new Vector3d(ik.Plugin.GetInput(0), ik.Plugin.GetInput(1), ik.Plugin.GetInput(2))), 9);
    }

    [Fact]
    public void Out_of_reach_the_force_is_the_stiffness_times_the_gap_and_the_error_is_its_length()
    {
        var chain = new KinematicChain(ShippedRobots.Lb);
        var state = chain.CreateState();
        var ik = Ik(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0", WorkspaceStiffnessNPerMm = 0.2 });
        var target = new Vector3d(600, 400, -300); // far beyond the arm's reach

        ik.Set(("x", target.X), ("y", target.Y), ("z", target.Z)).Tick(20);

        Assert.Equal(0.0, ik["reached"]);
        state.Update(Joints(ik, chain));
        var gap = state.ToolPosition - target; // reachable point minus demanded point
        Assert.Equal(0.2 * gap.X, ik["fx"], 9);
        Assert.Equal(0.2 * gap.Y, ik["fy"], 9);
        Assert.Equal(0.2 * gap.Z, ik["fz"], 9);
        Assert.Equal(gap.Length, ik["error_mm"], 9);
    }

    [Fact]
    public void A_non_finite_target_keeps_the_joints_and_pushes_nothing()
    {
        var chain = new KinematicChain(ShippedRobots.Lb);
        var ik = Ik(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" });
        ik.Set(("x", 600), ("y", 400), ("z", -300)).Tick(5); // out of reach: a force and a moved arm
        Assert.NotEqual(0.0, ik["fx"]);
        var before = Joints(ik, chain);

        ik.Set(("x", double.NaN)).Tick();

        Assert.Equal(before, Joints(ik, chain));
        Assert.Equal((0.0, 0.0, 0.0, 0.0), (ik["fx"], ik["fy"], ik["fz"], ik["reached"]));
    }

    [Fact]
    public void An_invalid_target_right_after_a_reached_one_clears_reached_and_keeps_everything_else()
    {
        var chain = new KinematicChain(ShippedRobots.Lb);
        var ik = Ik(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" });
        ik.Tick(); // the target is where the arm starts: reached
        Assert.Equal(1.0, ik["reached"]);
        var before = Joints(ik, chain);
        var error = ik["error_mm"];

        ik.Set(("y", double.PositiveInfinity)).Tick();

        Assert.Equal(0.0, ik["reached"]);
        Assert.Equal(before, Joints(ik, chain));
        Assert.Equal((0.0, 0.0, 0.0), (ik["fx"], ik["fy"], ik["fz"]));
        Assert.Equal(error, ik["error_mm"]); // the last solved error is kept, not overwritten by the invalid target's
    }

    [Fact]
    public void Initial_joints_beyond_the_limits_start_clamped_to_them()
    {
        // 400 deg and -400 deg lie beyond every joint's range of the LB-1.0.
        var chain = new KinematicChain(ShippedRobots.Lb);
        var ik = Ik(new InverseKinematicsSettings { InitialJointsDeg = "-400,-30,0,400,0" });

        var joints = Joints(ik, chain);

        Assert.Equal(chain.MinRad[0], joints[0], 12);
        Assert.Equal(chain.MaxRad[3], joints[3], 12);
        Assert.Equal(-30 * Math.PI / 180, joints[1], 12);
    }

    [Fact]
    public void Without_initial_joints_the_arm_starts_mid_range()
    {
        var chain = new KinematicChain(ShippedRobots.Lb);
        var ik = Ik(new InverseKinematicsSettings());

        var joints = Joints(ik, chain);

        for (var j = 0; j < chain.JointCount; j++)
        {
            Assert.Equal(0.5 * (chain.MinRad[j] + chain.MaxRad[j]), joints[j], 12);
        }
    }

    [Fact]
    public void Initial_joints_of_the_wrong_count_are_refused_naming_the_setting()
    {
        var ex = Assert.Throws<ArgumentException>(() => Ik(new InverseKinematicsSettings { InitialJointsDeg = "0,0,0" }));
        Assert.Contains("initial_joints_deg has 3 values", ex.Message, StringComparison.Ordinal);
    }
}
