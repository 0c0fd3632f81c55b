using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Graph;

/// <summary>What a plug-in knows at its first tick: which of its inputs are wired, and what its delayed inputs carry.</summary>
public sealed class GraphStartTests
{
    /// <summary>Shows 7 from its Start on (as the robot node shows the arm's joints), then 100 plus the tick index.</summary>
    private sealed class Publisher : Plugin
    {
        private readonly OutputPort _value;

        public Publisher()
            : base(PluginContext.Standalone("pub")) => _value = DeclareOutput("value", SafeValue.HoldLastFinite);

        public override void Start(in TickContext context) => Write(_value, 7);

        public override void Tick(in TickContext context) => Write(_value, 100 + context.Index);
    }

    /// <summary>Three inputs (initial value -1); records what each tick read and which inputs the graph wired.</summary>
    private sealed class Probe : Plugin
    {
        private readonly InputPort _direct;
        private readonly InputPort _delayed;
        private readonly InputPort _free;

        public Probe()
            : base(PluginContext.Standalone("probe"))
        {
            _direct = DeclareInput("direct", initialValue: -1);
            _delayed = DeclareInput("delayed", initialValue: -1);
            _free = DeclareInput("free", initialValue: -1);
        }

        public (bool Direct, bool Delayed, bool Free) WiredAtStart { get; private set; }

        public List<(double Direct, double Delayed, double Free)> Seen { get; } = [];

        public override void Start(in TickContext context) => WiredAtStart = (IsWired(_direct), IsWired(_delayed), IsWired(_free));

        public override void Tick(in TickContext context) => Seen.Add((Read(_direct), Read(_delayed), Read(_free)));
    }

    private static (Probe Probe, GraphProgram Program) Wired()
    {
        var graph = new PluginGraph();
        var probe = new Probe();
        graph.Add(probe);
        graph.Add(new Publisher());
        graph.Add(new CounterSource("count"));
        graph.Connect("count.value", "probe.direct");
        graph.Connect("pub.value", "probe.delayed", delayed: true); // the probe runs before the publisher
        return (probe, graph.Compile());
    }

    [Fact]
    public void A_plug_in_knows_from_its_start_which_inputs_are_wired_directly_or_delayed()
    {
        var (probe, program) = Wired();

        program.Start(Ticks.At(0));

        Assert.Equal((true, true, false), probe.WiredAtStart);
    }

    [Fact]
    public void The_first_tick_s_delayed_input_carries_what_its_source_showed_after_start_then_the_previous_tick_s_value()
    {
        var (probe, program) = Wired();

        Ticks.Run(program, 3);

        Assert.Equal([(0.0, 7.0, -1.0), (1.0, 100.0, -1.0), (2.0, 101.0, -1.0)], probe.Seen);
    }

    [Fact]
    public void Outside_a_graph_no_input_is_wired()
    {
        var probe = new Probe();

        probe.Start(Ticks.At(0));

        Assert.Equal((false, false, false), probe.WiredAtStart);
    }
}
