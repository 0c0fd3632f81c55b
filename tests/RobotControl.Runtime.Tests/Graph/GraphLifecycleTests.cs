using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Observation;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Tests.Support;
using RobotControl.TestSupport;

namespace RobotControl.Runtime.Tests.Graph;

/// <summary>Start and stop, observers, names and signal names: the graph's edges that mutation testing found open.</summary>
public sealed class GraphLifecycleTests
{
    /// <summary>Records start and stop calls in a shared log; may throw in either.</summary>
    private sealed class Lifecycle : Plugin
    {
        private readonly List<string> _log;
        private readonly bool _throwAtStart;
        private readonly bool _throwAtStop;
        private readonly OutputPort _out;
        private readonly OutputPort _zero;

        public Lifecycle(string name, List<string> log, double initial = 0, bool throwAtStart = false, bool throwAtStop = false)
            : base(PluginContext.Standalone(name))
        {
            _log = log;
            _throwAtStart = throwAtStart;
            _throwAtStop = throwAtStop;
            _out = DeclareOutput("out", SafeValue.HoldLastFinite, initialValue: initial);
            _zero = DeclareOutput("zero", SafeValue.Zero, initialValue: initial);
        }

        public int Ticks { get; private set; }

        public override void Start(in TickContext context)
        {
            _log.Add("start " + Name);
            if (_throwAtStart)
            {
                throw new InvalidOperationException("no device");
            }
        }

        public override void Tick(in TickContext context)
        {
            Ticks++;
            Write(_out, 42);
            Write(_zero, 42);
        }

        public override void Stop()
        {
            _log.Add("stop " + Name);
            if (_throwAtStop)
            {
                throw new InvalidOperationException("stuck");
            }
        }
    }

    /// <summary>An observer with one output, which may only feed other observers.</summary>
    private sealed class Watcher : Plugin, ISignalObserver
    {
        private readonly OutputPort _seen;
        private readonly InputPort _in;
        private readonly List<string>? _log;
        private SignalView? _view;

        public Watcher(string name, List<string>? log = null)
            : base(PluginContext.Standalone(name))
        {
            _log = log;
            _in = DeclareInput("in");
            _seen = DeclareOutput("seen", SafeValue.HoldLastFinite);
        }

        public bool Attached => _view is not null;

        public void Attach(SignalView view) => _view = view;

        public override void Tick(in TickContext context)
        {
            _log?.Add(Name);
            Write(_seen, Read(_in));
        }
    }

    [Fact]
    public void Starting_twice_is_refused()
    {
        var graph = new PluginGraph();
        graph.Add(new CounterSource("a"));
        var program = graph.Compile();
        program.Start(Ticks.At(0));

        Assert.Throws<InvalidOperationException>(() => program.Start(Ticks.At(0)));
    }

    /// <summary>Writes 42 to one output of each safe value (initial 7) until it throws, in tick 3.</summary>
    private sealed class ThrowsInTick3 : Plugin
    {
        private readonly OutputPort[] _outs;

        public ThrowsInTick3()
            : base(PluginContext.Standalone("thrower")) =>
            _outs = [DeclareOutput("hold", SafeValue.HoldLastFinite, initialValue: 7), DeclareOutput("zero", SafeValue.Zero, initialValue: 7), DeclareOutput("initial", SafeValue.Initial, initialValue: 7)];

        public override void Tick(in TickContext context)
        {
            if (context.Index == 3)
            {
                throw new InvalidOperationException("broken");
            }

            foreach (var o in _outs)
            {
                Write(o, 42);
            }
        }
    }

    [Fact]
    public void A_plug_in_that_faults_mid_run_leaves_each_output_at_its_safe_value_hold_zero_or_initial()
    {
        var graph = new PluginGraph();
        var thrower = new ThrowsInTick3();
        graph.Add(thrower);
        var program = graph.Compile();
        program.Start(Ticks.At(0));
        for (var k = 0; k < 5; k++)
        {
            program.Tick(Ticks.At(k));
        }

        Assert.True(program.IsFaulted("thrower"));
        Assert.Equal((42.0, 0.0, 7.0), (thrower.GetOutput("hold"), thrower.GetOutput("zero"), thrower.GetOutput("initial")));
    }

    [Fact]
    public void An_instance_that_fails_to_start_is_faulted_never_ticked_and_its_outputs_are_safe()
    {
        var log = new List<string>();
        var graph = new PluginGraph();
        var broken = new Lifecycle("broken", log, initial: 7, throwAtStart: true);
        var fine = new Lifecycle("fine", log, initial: 7);
        graph.Add(broken);
        graph.Add(fine);
        var program = graph.Compile();

        program.Start(Ticks.At(5));
        for (var k = 5; k < 8; k++)
        {
            program.Tick(Ticks.At(k));
        }

        Assert.Equal(["start broken", "start fine"], log); // the others still start
        Assert.True(program.IsFaulted("broken"));
        Assert.False(program.IsFaulted("fine"));
        Assert.Equal((0, 3), (broken.Ticks, fine.Ticks));
        Assert.Equal(7.0, broken.GetOutput("out")); // hold-last-finite holds its initial value
        Assert.Equal(0.0, broken.GetOutput("zero")); // zero goes to zero
        var fault = Assert.Single(program.Faults);
        Assert.Equal(("broken", 5L), (fault.Instance, fault.TickIndex));
        Assert.StartsWith("start failed: InvalidOperationException: no device", fault.Message, StringComparison.Ordinal);
        Assert.Equal(1, program.FaultCount);
    }

    [Fact]
    public void Stop_runs_once_in_reverse_order_and_records_failures_without_throwing()
    {
        var log = new List<string>();
        var graph = new PluginGraph();
        graph.Add(new Lifecycle("first", log));
        graph.Add(new Lifecycle("second", log, throwAtStop: true));
        graph.Add(new Lifecycle("third", log));
        var program = graph.Compile();

        program.Stop(); // never started: nothing to stop
        Assert.Empty(log);

        program.Start(Ticks.At(0));
        program.Stop();
        program.Stop(); // the second stop does nothing

        Assert.Equal(["start first", "start second", "start third", "stop third", "stop second", "stop first"], log);
        var fault = Assert.Single(program.Faults);
        Assert.Equal(("second", -1L), (fault.Instance, fault.TickIndex));
        Assert.Equal("stop failed: InvalidOperationException: stuck", fault.Message);
        Assert.Equal(1, program.FaultCount);
    }

    [Fact]
    public void Asking_about_an_unknown_instance_names_it()
    {
        var graph = new PluginGraph();
        graph.Add(new CounterSource("a"));
        var program = graph.Compile();

        var ex = Assert.Throws<ArgumentException>(() => program.IsFaulted("nope"));
        Assert.Contains("no instance 'nope'", ex.Message, StringComparison.Ordinal);
        Assert.Throws<ArgumentException>(() => program.NonFiniteOutputs("nope"));
        Assert.Equal(0, program.NonFiniteOutputs("a"));
    }

    [Fact]
    public void Observers_are_attached_and_run_after_everything_else_even_when_added_first()
    {
        var log = new List<string>();
        var graph = new PluginGraph();
        var watcher = new Watcher("watch", log);
        var second = new Watcher("watch2", log);
        graph.Add(watcher);
        graph.Add(new CounterSource("a", log));
        graph.Add(second);
        graph.Add(new Gain("g", log: log));
        graph.Connect("a.value", "g.in");
        graph.Connect("watch.seen", "watch2.in"); // an observer may feed another observer

        var program = graph.Compile();
        program.Start(Ticks.At(0));
        program.Tick(Ticks.At(0));

        Assert.Equal(["a", "g", "watch", "watch2"], log);
        Assert.True(watcher.Attached);
        Assert.True(second.Attached);
    }

    [Fact]
    public void An_observer_output_cannot_feed_an_ordinary_instance()
    {
        var graph = new PluginGraph();
        graph.Add(new Watcher("watch"));
        graph.Add(new Gain("g"));
        graph.Connect("watch.seen", "g.in");

        var ex = Assert.Throws<GraphException>(graph.Compile);
        Assert.Contains("'watch' observes every signal and runs last, so its output 'watch.seen' cannot feed 'g.in'", ex.Message, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("")]
    [InlineData(" ")]
    [InlineData("a.b")]
    [InlineData("a b")]
    [InlineData("tab\there")]
    public void Malformed_instance_names_are_refused(string name)
    {
        var graph = new PluginGraph();

        Assert.Contains("must be non-empty without dots or spaces", graph.CheckName(name), StringComparison.Ordinal);
        Assert.Null(graph.CheckName("fine_name-2"));
    }

    [Theory]
    [InlineData("x.")]
    [InlineData(".out")]
    [InlineData("xout")]
    public void A_source_that_is_not_instance_dot_port_is_refused(string from)
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));

        Assert.Equal($"'{from}' is not an instance.port signal name", graph.TryConnect(new Wire(from, "y.in", false)));
        Assert.Empty(graph.Wires);
    }

    [Fact]
    public void Unknown_ports_are_answered_with_the_ports_the_instance_has()
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));

        Assert.Equal("unknown output 'x.outt' (that instance has: x.force, x.out)", graph.TryConnect(new Wire("x.outt", "y.in", false)));
        Assert.Equal("unknown input 'y.inn' (that instance has: y.in, y.second)", graph.TryConnect(new Wire("x.out", "y.inn", false)));
        Assert.Equal("unknown input 'q.in'", graph.TryConnect(new Wire("x.out", "q.in", false)));
        Assert.Equal("input 'y.in' is already wired from 'x.out'; an input has one source", ConnectTwice(graph));
    }

    [Fact]
    public void Removing_an_instance_removes_the_wires_it_feeds_and_an_unknown_name_changes_nothing()
    {
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));
        graph.Add(new Gain("z"));
        graph.Connect("x.out", "y.in");
        graph.Connect("y.out", "z.in");

        Assert.False(graph.Remove("nope"));
        Assert.Equal(2, graph.Wires.Count);
        Assert.True(graph.Remove("x"));

        var left = Assert.Single(graph.Wires);
        Assert.Equal(("y.out", "z.in"), (left.From, left.To));
        Assert.Null(graph.Find("x"));
        Assert.Equal(["y", "z"], graph.Instances.Select(p => p.Name));
    }

    [Fact]
    public void A_port_name_may_itself_contain_dots_after_the_instance()
    {
        // The instance is everything before the first dot: "x.out.extra" names port "out.extra" of x, which x lacks.
        var graph = new PluginGraph();
        graph.Add(new Gain("x"));
        graph.Add(new Gain("y"));

        Assert.StartsWith("unknown output 'x.out.extra'", graph.TryConnect(new Wire("x.out.extra", "y.in", false)), StringComparison.Ordinal);
    }

    private static string? ConnectTwice(PluginGraph graph)
    {
        graph.Connect("x.out", "y.in");
        return graph.TryConnect(new Wire("x.force", "y.in", false));
    }
}
