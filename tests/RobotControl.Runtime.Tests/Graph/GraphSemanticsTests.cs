using RobotControl.Definitions.Json;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Graph;

public sealed class GraphSemanticsTests
{
    [Fact]
    public void Instances_run_in_dependency_order_whatever_order_they_were_added()
    {
        var log = new List<string>();
        var graph = new PluginGraph();
        graph.Add(new Gain("c", log: log));
        graph.Add(new Gain("b", log: log));
        graph.Add(new CounterSource("a", log));
        graph.Connect("b.out", "c.in");
        graph.Connect("a.value", "b.in");

        var program = graph.Compile();
        Ticks.Run(program, 1);

        Assert.Equal(["a", "b", "c"], log);
        Assert.Equal(["a", "b", "c"], program.Order.Select(p => p.Name));
    }

    [Fact]
    public void Values_flow_from_source_to_sink_within_one_tick()
    {
        var graph = new PluginGraph();
        var b = new Gain("b", 2.0);
        var c = new Gain("c", 10.0);
        graph.Add(new CounterSource("a"));
        graph.Add(b);
        graph.Add(c);
        graph.Connect("a.value", "b.in");
        graph.Connect("b.out", "c.in");

        Ticks.Run(graph.Compile(), 4);

        Assert.Equal([0.0, 1, 2, 3], b.Seen);
        Assert.Equal([0.0, 2, 4, 6], c.Seen);
        Assert.Equal(60.0, c.GetOutput("out"));
    }

    [Fact]
    public void An_output_fans_out_to_every_wired_input()
    {
        var graph = new PluginGraph();
        var sinks = Enumerable.Range(0, 3).Select(i => new Gain($"s{i}")).ToList();
        graph.Add(new CounterSource("a"));
        foreach (var s in sinks)
        {
            graph.Add(s);
            graph.Connect("a.value", $"{s.Name}.in");
            graph.Connect("a.value", $"{s.Name}.second");
        }

        Ticks.Run(graph.Compile(), 3);

        Assert.All(sinks, s => Assert.Equal([0.0, 1, 2], s.Seen));
        Assert.All(sinks, s => Assert.Equal(4.0, s.GetOutput("out")));
    }

    [Fact]
    public void A_delayed_feedback_wire_delivers_the_previous_ticks_value()
    {
        // a -> b -> c, and c.out feeds back into b.second one tick later: b.out(k) = a(k) + c.out(k-1).
        var graph = new PluginGraph();
        var b = new Gain("b");
        var c = new Gain("c");
        graph.Add(new CounterSource("a"));
        graph.Add(b);
        graph.Add(c);
        graph.Connect("a.value", "b.in");
        graph.Connect("b.out", "c.in");
        graph.Connect("c.out", "b.second", delayed: true);

        var program = graph.Compile();
        program.Start(Ticks.At(0));
        var outputs = new List<double>();
        for (var k = 0; k < 5; k++)
        {
            program.Tick(Ticks.At(k));
            outputs.Add(b.GetOutput("out"));
        }

        // k=0: 0+0; k=1: 1+0=1; k=2: 2+1=3; k=3: 3+3=6; k=4: 4+6=10.
        Assert.Equal([0.0, 1, 3, 6, 10], outputs);
    }

    [Fact]
    public void A_cycle_without_a_delayed_wire_is_rejected_naming_the_cycle()
    {
        var graph = new PluginGraph();
        graph.Add(new CounterSource("src"));
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));
        graph.Add(new Gain("z"));
        graph.Connect("src.value", "x.in");
        graph.Connect("x.out", "y.in");
        graph.Connect("y.out", "z.in");
        graph.Connect("z.out", "x.second");

        var ex = Assert.Throws<GraphException>(graph.Compile);

        var problem = Assert.Single(ex.Problems);
        Assert.Contains("cycle", problem.Message, StringComparison.Ordinal);
        Assert.Contains("x -> y -> z -> x", problem.Message.Replace("y -> z -> x -> y", "x -> y -> z -> x", StringComparison.Ordinal)
            .Replace("z -> x -> y -> z", "x -> y -> z -> x", StringComparison.Ordinal), StringComparison.Ordinal);
        Assert.Contains("z.out -> x.second", problem.Message, StringComparison.Ordinal);
        Assert.DoesNotContain("src", problem.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void The_same_cycle_compiles_once_one_wire_is_delayed()
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));
        graph.Connect("x.out", "y.in");
        graph.Connect("y.out", "x.in", delayed: true);

        var program = graph.Compile();

        Assert.Equal(["x", "y"], program.Order.Select(p => p.Name));
    }

    [Fact]
    public void Wiring_errors_name_the_problem()
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));
        graph.Connect("x.out", "y.in");

        Assert.Contains("unknown output 'x.nope'", graph.TryConnect(new Wire("x.nope", "y.second", false)), StringComparison.Ordinal);
        Assert.Contains("is an input", graph.TryConnect(new Wire("x.in", "y.second", false)), StringComparison.Ordinal);
        Assert.Contains("is an output", graph.TryConnect(new Wire("x.out", "y.out", false)), StringComparison.Ordinal);
        Assert.Contains("already wired", graph.TryConnect(new Wire("x.force", "y.in", false)), StringComparison.Ordinal);
        Assert.Contains("unknown instance", graph.TryConnect(new Wire("q.out", "y.second", false)), StringComparison.Ordinal);
        Assert.Contains("duplicate", graph.CheckName("x"), StringComparison.Ordinal);
    }

    [Fact]
    public void Removing_an_instance_removes_its_inputs_from_the_registry_and_its_wires()
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));
        graph.Connect("x.out", "y.in");
        Assert.Contains("y.in", graph.RegisteredInputs);

        Assert.True(graph.Remove("y"));

        Assert.DoesNotContain("y.in", graph.RegisteredInputs);
        Assert.Empty(graph.Wires);
    }

    [Fact]
    public void A_throwing_plugin_is_isolated_its_outputs_go_safe_and_downstream_sees_the_fault()
    {
        var graph = new PluginGraph();
        var faulty = new Gain("faulty", 2.0) { ThrowAtTick = 3 };
        var down = new Gain("down");
        var other = new Gain("other");
        graph.Add(new CounterSource("a"));
        graph.Add(faulty);
        graph.Add(down);
        graph.Add(other);
        graph.Connect("a.value", "faulty.in");
        graph.Connect("faulty.out", "down.in");
        graph.Connect("a.value", "other.in");

        var program = graph.Compile();
        Ticks.Run(program, 6);

        Assert.True(program.IsFaulted("faulty"));
        Assert.False(program.IsFaulted("other"));
        var fault = Assert.Single(program.Faults);
        Assert.Equal("faulty", fault.Instance);
        Assert.Equal(3, fault.TickIndex);
        Assert.Contains("boom", fault.Message, StringComparison.Ordinal);
        Assert.Equal(4.0, faulty.GetOutput("out")); // held at the last finite value (tick 2: 2 * 2)
        Assert.Equal(0.0, faulty.GetOutput("force")); // declared safe value zero
        Assert.Equal([0.0, 2, 4, 4, 4, 4], down.Seen); // keeps running on the safe value
        Assert.Equal([0.0, 1, 2, 3, 4, 5], other.Seen); // unaffected
    }

    [Fact]
    public void Non_finite_outputs_never_leave_a_plugin()
    {
        var graph = new PluginGraph();
        var nan = new Gain("nan") { NaNAtTick = 2 };
        var down = new Gain("down");
        var forced = new Gain("forced");
        graph.Add(new CounterSource("a"));
        graph.Add(nan);
        graph.Add(down);
        graph.Add(forced);
        graph.Connect("a.value", "nan.in");
        graph.Connect("nan.out", "down.in");
        graph.Connect("nan.force", "forced.in");

        var program = graph.Compile();
        Ticks.Run(program, 4);

        Assert.Equal([0.0, 1, 1, 3], down.Seen); // out: hold the last finite value
        Assert.Equal([0.0, 1, 0, 3], forced.Seen); // force: its declared safe value, zero
        Assert.Equal(2, program.NonFiniteOutputs("nan")); // out held at 1, force zeroed
        Assert.False(program.IsFaulted("nan"));
    }

    [Fact]
    public void The_message_of_an_invalid_graph_names_the_file_counts_the_problems_and_lists_each_on_its_own_line_or_is_one_line_for_one()
    {
        var nl = Environment.NewLine;
        var two = new GraphException([new JsonProblem("wires[0].to", "no such input"), new JsonProblem("instances[1].type", "unknown type")], "g.json");
        Assert.Equal($"g.json: invalid graph (2 problems):{nl}  wires[0].to: no such input{nl}  instances[1].type: unknown type", two.Message);
        var one = new GraphException([new JsonProblem("", "graph has a cycle")]);
        Assert.Equal("invalid graph: graph has a cycle", one.Message);
        Assert.Equal(("g.json", 2), (two.File, two.Problems.Count));
    }
}
