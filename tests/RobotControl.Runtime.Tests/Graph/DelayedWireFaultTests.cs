using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Tests.Support;

using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Graph;

public sealed class DelayedWireFaultTests
{
    [Fact]
    public void A_fault_behind_a_delayed_wire_reaches_the_instances_it_feeds_from_the_next_tick_on()
    {
        // a -> watcher -> thrower, and thrower.out feeds back into watcher.second one tick later. The thrower faults
        // at tick 3; the watcher runs before it in that tick, so it learns of the fault at tick 4 through the delayed
        // wire, exactly as it would see any value from the thrower.
        var graph = new PluginGraph();
        var watcher = new FaultWatcher("watcher");
        var bystander = new FaultWatcher("bystander");
        graph.Add(new CounterSource("a"));
        graph.Add(watcher);
        graph.Add(new Gain("thrower") { ThrowAtTick = 3 });
        graph.Add(bystander);
        graph.Connect("a.value", "watcher.in");
        graph.Connect("watcher.out", "thrower.in");
        graph.Connect("thrower.out", "watcher.second", delayed: true);
        graph.Connect("a.value", "bystander.in");

        Ticks.Run(graph.Compile(), 7);

        Assert.Equal([false, false, false, false, true, true, true], watcher.UpstreamFaults);
        Assert.All(bystander.UpstreamFaults, Assert.False);
    }

    [Fact]
    public void Faults_on_a_direct_and_a_delayed_wire_at_once_still_mark_the_instance_as_downstream_of_a_fault()
    {
        // a -> first (faults at tick 1) -> watcher -> second (faults at tick 1) -> watcher.second, delayed. From tick 2
        // on the watcher hears of both faults together; two faults must not cancel out.
        var graph = new PluginGraph();
        var watcher = new FaultWatcher("watcher");
        graph.Add(new CounterSource("a"));
        graph.Add(new Gain("first") { ThrowAtTick = 1 });
        graph.Add(watcher);
        graph.Add(new Gain("second") { ThrowAtTick = 1 });
        graph.Connect("a.value", "first.in");
        graph.Connect("first.out", "watcher.in");
        graph.Connect("watcher.out", "second.in");
        graph.Connect("second.out", "watcher.second", delayed: true);

        Ticks.Run(graph.Compile(), 4);

        Assert.Equal([false, true, true, true], watcher.UpstreamFaults);
    }

    private sealed class FaultWatcher : Plugin
    {
        private readonly InputPort _in;
        private readonly OutputPort _out;

        public FaultWatcher(string name)
            : base(PluginContext.Standalone(name))
        {
            _in = DeclareInput("in");
            DeclareInput("second");
            _out = DeclareOutput("out", SafeValue.HoldLastFinite);
        }

        public List<bool> UpstreamFaults { get; } = [];

        public override void Tick(in TickContext context)
        {
            UpstreamFaults.Add(UpstreamFaulted);
            Write(_out, Read(_in));
        }
    }
}
