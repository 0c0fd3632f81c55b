using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Robot;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Robot;

public sealed class RobotNodeTests
{
    private sealed class ElbowSource : Plugin
    {
        private readonly OutputPort _elbow;
        private readonly long _throwAt;

        public ElbowSource(long throwAt)
            : base(PluginContext.Standalone("src"))
        {
            _throwAt = throwAt;
            _elbow = DeclareOutput("elbow", SafeValue.HoldLastFinite, "rad");
        }

        public override void Tick(in TickContext context)
        {
            if (context.Index == _throwAt)
            {
                throw new InvalidOperationException("source broke");
            }

            Write(_elbow, 0.5 + (0.001 * context.Index));
        }
    }

    private sealed class SpeedSource : Plugin
    {
        private readonly OutputPort _speed;
        private readonly long _jumpAt;

        public SpeedSource(long jumpAt)
            : base(PluginContext.Standalone("hand"))
        {
            _jumpAt = jumpAt;
            _speed = DeclareOutput("speed_mm_s", SafeValue.HoldLastFinite, "mm/s");
        }

        public override void Tick(in TickContext context) => Write(_speed, context.Index == _jumpAt ? 50_000 : 100);
    }

    [Fact]
    public void A_speed_the_operator_port_calls_implausible_publishes_nothing_for_that_arm_that_tick_and_every_tick_is_reported()
    {
        var port = new KinematicRobotPort(Repo.Lb) { SpeedLimitMmPerS = 2000 };
        var node = new RobotNode(Repo.Lb, TimeProvider.System, Repo.Root);
        node.Attach(port, port);
        var graph = new PluginGraph();
        graph.Add(node);
        graph.Add(new ElbowSource(throwAt: -1));
        graph.Add(new SpeedSource(jumpAt: 5));
        graph.Connect("src.elbow", "robot.right.elbow");
        graph.Connect("hand.speed_mm_s", "robot.right.input_speed_mm_s");
        node.SetDriven(graph.Wires.Select(w => w.To));

        Ticks.Run(graph.Compile(), 10);

        Assert.Equal(10, port.Ticks);
        Assert.Equal(9, port.Writes); // tick 5 published nothing
        var q = new double[5];
        port.ReadJointPositions(0, q);
        Assert.Equal(0.509, q[3], 9);
    }

    [Fact]
    public void The_robot_shows_its_joints_as_inputs_and_positions_currents_faults_as_outputs()
    {
        var node = new RobotNode(Repo.Lb, TimeProvider.System, Repo.Root);

        Assert.Contains(node.Inputs, p => p.Name == "right.elbow" && p.Units == "rad");
        Assert.Contains(node.Inputs, p => p.Name == "left.jaw");
        Assert.Contains(node.Outputs, p => p.Name == "left.shoulder_roll.position");
        Assert.Contains(node.Outputs, p => p.Name == "right.tool_open_close.current" && p.Units == "A");
        Assert.Contains(node.Outputs, p => p.Name == "faults");
    }

    [Fact]
    public void Teleop_enabled_follows_the_port_s_run_level_and_drops_when_an_upstream_plugin_faults()
    {
        var (port, node, program) = ElbowDriven(throwAt: 10);

        program.Start(Ticks.At(0));
        var seen = new double[12];
        for (var i = 0; i < seen.Length; i++)
        {
            port.TeleopAllowed = i is not (3 or 4); // e.g. a trip at tick 3, reset before tick 5
            program.Tick(Ticks.At(i));
            seen[i] = node.GetOutput("teleop_enabled");
        }

        // The source faults at tick 10: the robot holds, and teleoperation stays off.
        Assert.Equal([1, 1, 1, 0, 0, 1, 1, 1, 1, 1, 0, 0], seen);
    }

    [Fact]
    public void When_an_upstream_plugin_faults_the_robot_holds_position_and_is_sent_nothing_more()
    {
        var (port, node, program) = ElbowDriven(throwAt: 10);

        Ticks.Run(program, 20);

        Assert.Equal(10, port.Writes); // ticks 0..9 only
        Assert.Equal(1, port.Holds);
        Assert.True(node.Holding);
        var q = new double[5];
        port.ReadJointPositions(0, q);
        Assert.Equal(0.509, q[3], 9); // where tick 9 put it
        Assert.Equal(Repo.Lb.Joints[0].MidRad, q[0], 9); // unwired joints kept the position read at start
    }

    /// <summary>The robot node on a kinematic port, its right elbow driven by a source that throws at tick <paramref name="throwAt"/>.</summary>
    private static (KinematicRobotPort Port, RobotNode Node, GraphProgram Program) ElbowDriven(long throwAt)
    {
        var port = new KinematicRobotPort(Repo.Lb);
        var node = new RobotNode(Repo.Lb, TimeProvider.System, Repo.Root);
        node.Attach(port, port);
        var graph = new PluginGraph();
        graph.Add(node);
        graph.Add(new ElbowSource(throwAt));
        graph.Connect("src.elbow", "robot.right.elbow");
        node.SetDriven(graph.Wires.Select(w => w.To));
        return (port, node, graph.Compile());
    }
}
