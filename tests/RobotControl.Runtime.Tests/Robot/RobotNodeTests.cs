using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Robot;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Robot;

public sealed class RobotNodeTests
{
    /// <summary>A plug-in <paramref name="name"/> with one output whose value each tick is <paramref name="value"/> of the tick's index (which may throw).</summary>
    private sealed class Source : Plugin
    {
        private readonly OutputPort _output;
        private readonly Func<long, double> _value;

        public Source(string name, string output, Func<long, double> value)
            : base(PluginContext.Standalone(name))
        {
            _value = value;
            _output = DeclareOutput(output, SafeValue.HoldLastFinite);
        }

        public override void Tick(in TickContext context) => Write(_output, _value(context.Index));
    }

    /// <summary>The right elbow's setpoint source (<c>src.elbow</c>): 0.5 rad plus 1 mrad per tick, throwing at tick <paramref name="throwAt"/>.</summary>
    private static Source ElbowSource(long throwAt) =>
        new("src", "elbow", i => i == throwAt ? throw new InvalidOperationException("source broke") : 0.5 + (0.001 * i));

    [Fact]
    public void A_speed_the_operator_port_calls_implausible_publishes_nothing_for_that_arm_that_tick_and_every_tick_is_reported()
    {
        var port = new KinematicRobotPort(Repo.Lb) { SpeedLimitMmPerS = 2000 };
        var node = new RobotNode(Repo.Lb, TimeProvider.System, Repo.Root);
        node.Attach(port, port);
        var graph = new PluginGraph();
        graph.Add(node);
        graph.Add(ElbowSource(throwAt: -1));
        graph.Add(new Source("hand", "speed_mm_s", i => i == 5 ? 50_000 : 100)); // a jump at tick 5
        graph.Connect("src.elbow", "robot.right.elbow");
        graph.Connect("hand.speed_mm_s", "robot.right.input_speed_mm_s");

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
        graph.Add(ElbowSource(throwAt));
        graph.Connect("src.elbow", "robot.right.elbow");
        return (port, node, graph.Compile());
    }
}
