using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Testing;
using RobotControl.Plugins.Standard.Kinematics;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Robot;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Kinematics;

/// <summary>
/// Teleoperation starts where the arm is: the IK with <c>follow</c> and the measured joints wired (as in the shipped
/// graphs), in a graph with the robot node, on an ideal robot that starts away from where the target maps.
/// </summary>
public sealed class TeleopStartTests
{
    private static readonly double[] StartJointsDeg = [-30, -30, 0, 90, 0]; // the IK's initial joints in the shipped graphs

    /// <summary>A hand: the target position per tick.</summary>
    private sealed class Hand : Plugin
    {
        private readonly OutputPort _x;
        private readonly OutputPort _y;
        private readonly OutputPort _z;

        public Hand(Func<long, Vector3d> at)
            : base(PluginContext.Standalone("hand"))
        {
            At = at;
            _x = DeclareOutput("x", SafeValue.HoldLastFinite, "mm");
            _y = DeclareOutput("y", SafeValue.HoldLastFinite, "mm");
            _z = DeclareOutput("z", SafeValue.HoldLastFinite, "mm");
        }

        public Func<long, Vector3d> At { get; set; }

        public override void Tick(in TickContext context)
        {
            var p = At(context.Index);
            Write(_x, p.X);
            Write(_y, p.Y);
            Write(_z, p.Z);
        }
    }

    private sealed class Rig
    {
        private readonly ChainState _state;
        private readonly double[] _q;
        private long _tick;

        public Rig(Func<long, Vector3d> hand)
        {
            var robot = ShippedRobots.Lb;
            Chain = new KinematicChain(robot);
            _state = Chain.CreateState();
            _q = new double[Chain.JointCount];
            Port = new KinematicRobotPort(robot); // at mid-range: not where the hand's target maps
            Hand = new Hand(hand);
            var node = new RobotNode(robot, TimeProvider.System, RepositoryPaths.Root);
            node.Attach(Port, Port);
            var graph = new PluginGraph();
            graph.Add(Hand);
            graph.Add(new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = string.Join(',', StartJointsDeg) }, PluginContext.Standalone("ik", robot)));
            graph.Add(node);
            foreach (var c in new[] { "x", "y", "z" })
            {
                graph.Connect($"hand.{c}", $"ik.{c}");
            }

            foreach (var j in robot.Joints)
            {
                graph.Connect($"ik.{j.Name}", $"robot.right.{j.Name}");
                graph.Connect($"robot.right.{j.Name}.position", $"ik.{j.Name}.measured", delayed: true);
            }

            graph.Connect("robot.teleop_enabled", "ik.follow", delayed: true);
            Program = graph.Compile();
            Program.Start(Ticks.At(0));
        }

        public KinematicChain Chain { get; }

        public KinematicRobotPort Port { get; }

        public Hand Hand { get; }

        public GraphProgram Program { get; }

        /// <summary>Where the right arm's tool is now.</summary>
        public Vector3d Tool
        {
            get
            {
                Port.ReadJointPositions(0, _q);
                _state.Update(_q);
                return _state.ToolPosition;
            }
        }

        public void Tick(int count = 1)
        {
            for (var i = 0; i < count; i++)
            {
                Program.Tick(Ticks.At(_tick++));
            }
        }
    }

    private static Vector3d ToolAt(double[] jointsRad)
    {
        var state = new KinematicChain(ShippedRobots.Lb).CreateState();
        state.Update(jointsRad);
        return state.ToolPosition;
    }

    private static Vector3d StartTarget => ToolAt([.. StartJointsDeg.Select(d => d * Math.PI / 180)]);

    [Fact]
    public void The_first_pedal_down_moves_nothing_and_then_the_arm_moves_by_the_hand_s_motion()
    {
        var hand = StartTarget; // where the graph's first command would put the tool
        var rig = new Rig(i => hand + new Vector3d(0.01 * i, 0, 0)); // 10 mm/s along x
        var start = rig.Tool;
        Assert.True(Vector3d.Distance(start, hand) > 10, $"the arm starts {Vector3d.Distance(start, hand):F1} mm from the target: the test needs a gap");

        rig.Tick(); // teleoperation allowed from the first tick (a pedal pressed before the loop started)

        Assert.True(Vector3d.Distance(rig.Tool, start) < 0.02, $"the first command moved the tool {Vector3d.Distance(rig.Tool, start):F3} mm");
        rig.Tick(100);
        var moved = rig.Tool - start;
        Assert.Equal(1.0, moved.X, 1); // 100 ticks of 0.01 mm, within the IK's tolerance
        Assert.True(Math.Abs(moved.Y) < 0.02 && Math.Abs(moved.Z) < 0.02, $"moved {moved}");
    }

    [Fact]
    public void Re_engaging_after_the_arm_was_moved_and_the_hand_went_40_mm_starts_where_the_arm_is_now()
    {
        var hand = StartTarget;
        var rig = new Rig(_ => hand);
        rig.Tick(10);
        rig.Port.TeleopAllowed = false; // a soft trip: the robot holds
        rig.Tick(5);
        double[] moved = [0.1, -0.5, 0.05, 1.2, 0.2]; // the arm was put elsewhere meanwhile
        rig.Port.MoveTo(0, moved);
        rig.Hand.At = _ => hand + new Vector3d(40, 0, 0); // and the hand went 40 mm
        rig.Tick(10);
        var held = ToolAt(moved);
        Assert.Equal(0.0, Vector3d.Distance(rig.Tool, held), 9); // the port held: the test double moves only when allowed

        rig.Port.TeleopAllowed = true;
        rig.Tick(3);

        Assert.True(Vector3d.Distance(rig.Tool, held) < 0.02, $"re-engaging moved the tool {Vector3d.Distance(rig.Tool, held):F3} mm");
        rig.Hand.At = _ => hand + new Vector3d(40, 2, 0); // the hand moves 2 mm along y
        rig.Tick(20);
        var step = rig.Tool - held;
        Assert.Equal(2.0, step.Y, 1);
        Assert.True(Math.Abs(step.X) < 0.02 && Math.Abs(step.Z) < 0.02, $"moved {step}");
    }

    [Fact]
    public void Unwired_the_target_is_used_as_it_is()
    {
        var robot = ShippedRobots.Lb;
        using var ik = PluginHarness.Create(c => new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" }, c), robot: robot);
        var target = StartTarget + new Vector3d(5, 0, 0);
        ik.Set("x", target.X).Set("y", target.Y).Set("z", target.Z).Set("follow", 0).Set("elbow.measured", 0.3);

        ik.Tick(5); // follow set but not wired: ignored, as are the measured joints

        Assert.Equal(1.0, ik["reached"]);
        Assert.True(Vector3d.Distance(ToolAt([.. robot.Joints.Select(j => ik[j.Name])]), target) < 0.02);
    }

    [Fact]
    public void While_the_robot_does_not_follow_the_joints_out_are_the_measured_ones_and_nothing_is_pushed()
    {
        var robot = ShippedRobots.Lb;
        using var ik = PluginHarness.Create(c => new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" }, c), robot: robot);
        ik.Wire([.. robot.Joints.Select(j => $"{j.Name}.measured").Append("follow")]);
        double[] measured = [0.1, -0.5, 0.05, 1.2, 0.2];
        for (var j = 0; j < measured.Length; j++)
        {
            ik.Set($"{robot.Joints[j].Name}.measured", measured[j]);
        }

        ik.Set("x", 600).Set("y", 400).Set("z", -300).Set("follow", 0).Tick(3); // out of reach: would push

        Assert.Equal(measured, robot.Joints.Select(j => ik[j.Name]).ToArray());
        Assert.Equal((0.0, 0.0, 0.0, 0.0), (ik["fx"], ik["fy"], ik["fz"], ik["reached"]));
    }

    [Fact]
    public void Wired_but_without_every_measured_joint_the_target_is_used_as_it_is()
    {
        var robot = ShippedRobots.Lb;
        using var ik = PluginHarness.Create(c => new InverseKinematicsPlugin(new InverseKinematicsSettings { InitialJointsDeg = "-30,-30,0,90,0" }, c), robot: robot);
        ik.Wire("follow", "elbow.measured"); // the other joints' measurements are missing: no anchoring on a guess
        var target = StartTarget + new Vector3d(0, 5, 0);

        ik.Set("x", target.X).Set("y", target.Y).Set("z", target.Z).Set("follow", 1).Tick(5);

        Assert.True(Vector3d.Distance(ToolAt([.. robot.Joints.Select(j => ik[j.Name])]), target) < 0.02);
    }
}
