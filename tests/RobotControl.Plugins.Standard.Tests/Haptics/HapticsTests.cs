using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Standard.Haptics;
using RobotControl.Plugins.Standard.Kinematics;
using RobotControl.Runtime.Graph;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Haptics;

public sealed class HapticsTests
{
    private static readonly HomingSettings Homing = new() { OriginXMm = 108.97, OriginYMm = 37.07, OriginZMm = -43.79, RollDeg = 90, YawDeg = 15 };
    private const double Ratio = 0.5;

    private sealed class DevicePoint : Plugin
    {
        private readonly RobotControl.Plugins.Sdk.Ports.OutputPort[] _out;

        public DevicePoint()
            : base(PluginContext.Standalone("device"))
        {
            _out = [DeclareOutput("x", RobotControl.Plugins.Sdk.Ports.SafeValue.HoldLastFinite), DeclareOutput("y", RobotControl.Plugins.Sdk.Ports.SafeValue.HoldLastFinite), DeclareOutput("z", RobotControl.Plugins.Sdk.Ports.SafeValue.HoldLastFinite)];
        }

        public Vector3d Position { get; set; }

        public override void Tick(in TickContext context)
        {
            Write(_out[0], Position.X);
            Write(_out[1], Position.Y);
            Write(_out[2], Position.Z);
        }
    }

    private static (GraphProgram Program, DevicePoint Device, InverseKinematicsPlugin Ik, HapticWallsPlugin Walls) Chain(bool mirror)
    {
        var context = (string name) => PluginContext.Standalone(name, ShippedRobots.Lb);
        var homing = Homing with { Mirror = mirror };
        var device = new DevicePoint();
        var ik = new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" }, context("ik"));
        var walls = new HapticWallsPlugin(new HapticWallsSettings { RollDeg = homing.RollDeg, YawDeg = homing.YawDeg, Mirror = mirror, ScaleRatio = Ratio, MaxForceN = 10 }, context("walls"));
        var graph = new PluginGraph();
        graph.Add(device);
        graph.Add(new HomingPlugin(homing, context("homing")));
        graph.Add(new ScalingPlugin(new ScalingSettings { Ratio = Ratio, ReferenceXMm = homing.OriginXMm, ReferenceYMm = homing.OriginYMm, ReferenceZMm = homing.OriginZMm }, context("scaling")));
        graph.Add(ik);
        graph.Add(walls);
        foreach (var a in new[] { "x", "y", "z" })
        {
            graph.Connect($"device.{a}", $"homing.{a}");
            graph.Connect($"homing.{a}", $"scaling.{a}");
            graph.Connect($"scaling.{a}", $"ik.{a}");
            graph.Connect($"ik.f{a}", $"walls.f{a}");
        }

        var program = graph.Compile();
        program.Start(Ticks.At(0));
        return (program, device, ik, walls);
    }

    [Theory]
    [InlineData(false)]
    [InlineData(true)]
    public void Walls_push_the_handle_toward_the_reachable_point_in_the_device_frame(bool mirror)
    {
        var (program, device, ik, walls) = Chain(mirror);
        var frame = new DeviceFrame(Homing.RollDeg, 0, Homing.YawDeg, false, false, false, mirror);
        var origin = new Vector3d(Homing.OriginXMm, Homing.OriginYMm, Homing.OriginZMm);

        // Inside the workspace: no force.
        device.Position = new Vector3d(10, 5, -8);
        program.Tick(Ticks.At(0));
        Assert.Equal(1.0, ik.GetOutput("reached"));
        Assert.Equal(0.0, walls.GetOutput("fx"), 9);

        // Far outside (the device pulled 300 mm out, 150 mm at the robot): the force points back to the reachable point.
        for (var k = 1; k < 20; k++)
        {
            device.Position = frame.ToDevice(new Vector3d(1, 0.3, -0.2).Normalized() * 300.0);
            program.Tick(Ticks.At(k));
        }

        Assert.Equal(0.0, ik.GetOutput("reached"));
        var state = ik.Chain.CreateState();
        state.Update([.. ik.Outputs.Take(ik.Chain.JointCount).Select((_, j) => ik.GetOutput(j))]);
        var reachedDevice = frame.ToDevice(((state.ToolPosition - origin) / Ratio));
        var toReachable = reachedDevice - device.Position;
        var force = new Vector3d(walls.GetOutput("fx"), walls.GetOutput("fy"), walls.GetOutput("fz"));
        Assert.True(force.Length > 0.5, $"force {force}");
        Assert.True(Vector3d.Dot(force.Normalized(), toReachable.Normalized()) > 0.999, $"force {force} vs direction {toReachable}");
    }

    [Fact]
    public void Walls_clamp_each_axis_and_honour_the_sign_settings()
    {
        var walls = new PluginDriver(new HapticWallsPlugin(new HapticWallsSettings { MaxForceN = 1.5, InvertForceY = true }, PluginContext.Standalone("w")));

        walls.Set(("fx", 5), ("fy", 0.5), ("fz", -0.2)).Tick();

        Assert.Equal((1.5, -0.5, -0.2), (walls["fx"], walls["fy"], walls["fz"]));
    }

    [Fact]
    public void Damping_opposes_the_handle_velocity()
    {
        var damping = new PluginDriver(new ViscousDampingPlugin(new ViscousDampingSettings { DampingNsPerMm = 0.004, MaxForceN = 5 }, PluginContext.Standalone("d")));
        for (var k = 0; k < 500; k++)
        {
            damping.Set(("x", 0.1 * k), ("y", -0.05 * k), ("z", 3), ("fz_in", 0.25)).Tick(); // 100 mm/s and -50 mm/s
        }

        Assert.Equal(-0.4, damping["fx"], 3);
        Assert.Equal(0.2, damping["fy"], 3);
        Assert.Equal(0.25, damping["fz"], 3);
    }

    [Fact]
    public void The_lock_holds_the_handle_at_the_lock_point_and_pauses_the_pose()
    {
        var lockPlugin = new PluginDriver(new HapticLockPlugin(new HapticLockSettings { StiffnessNPerMm = 0.5, MaxForceN = 10 }, PluginContext.Standalone("l")));
        lockPlugin.Set(("x", 10), ("y", 20), ("z", 30)).Tick();
        Assert.Equal((10.0, 20.0, 30.0), lockPlugin.Xyz());

        lockPlugin.Set(("lock", 1)).Tick();
        lockPlugin.Set(("x", 14), ("y", 18), ("z", 30)).Tick(5);

        Assert.Equal((10.0, 20.0, 30.0), lockPlugin.Xyz()); // paused
        Assert.Equal((-2.0, 1.0, 0.0), (lockPlugin["fx"], lockPlugin["fy"], lockPlugin["fz"])); // spring back to the lock point
        Assert.Equal(1.0, lockPlugin["locked"]);

        lockPlugin.Set(("lock", 0)).Tick();
        Assert.Equal((10.0, 20.0, 30.0), lockPlugin.Xyz()); // no jump on unlock
        Assert.Equal(0.0, lockPlugin["fx"]);
        lockPlugin.Set(("x", 15)).Tick();
        Assert.Equal(11.0, lockPlugin["x"], 9); // then follows relative motion
    }

    [Fact]
    public void Inverse_kinematics_outputs_joints_whose_forward_kinematics_reach_the_target()
    {
        var ik = new PluginDriver(new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" }, PluginContext.Standalone("ik", ShippedRobots.Lb)));
        var chain = new KinematicChain(ShippedRobots.Lb);
        var state = chain.CreateState();

        ik.Set(("x", 100), ("y", 40), ("z", -50)).Tick();

        state.Update([.. Enumerable.Range(0, chain.JointCount).Select(j => ik.Plugin.GetOutput(j))]);
        Assert.Equal(1.0, ik["reached"]);
        Assert.True(Vector3d.Distance(state.ToolPosition, new Vector3d(100, 40, -50)) < 0.02);
        Assert.Equal(0.0, ik["fx"]);
    }
}
