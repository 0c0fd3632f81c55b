using RobotControl.Plugins.Sdk;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;

namespace RobotControl.Runtime.Tests.Graph;

public sealed class TickProfileTests
{
    /// <summary>Ticks quickly until <paramref name="from"/>, then blocks in its tick until released (a tick that never returns).</summary>
    private sealed class Stuck(string name, long from) : Plugin(PluginContext.Standalone(name))
    {
        public ManualResetEventSlim Release { get; } = new();

        /// <summary>Set once a tick is stuck (inside it, so the profile has it as the plug-in in its tick).</summary>
        public ManualResetEventSlim Entered { get; } = new();

        public bool Stopped { get; private set; }

        public override void Tick(in TickContext context)
        {
            if (context.Index >= from)
            {
                Entered.Set();
                Release.Wait();
            }
        }

        public override void Stop() => Stopped = true;
    }

    /// <summary>Spins <paramref name="spinTicks"/> Stopwatch ticks each tick.</summary>
    private sealed class Busy(string name, long spinTicks) : Plugin(PluginContext.Standalone(name))
    {
        public override void Tick(in TickContext context)
        {
            var until = System.Diagnostics.Stopwatch.GetTimestamp() + spinTicks;
            while (System.Diagnostics.Stopwatch.GetTimestamp() < until)
            {
            }
        }
    }

    private sealed class Idle(string name) : Plugin(PluginContext.Standalone(name))
    {
        public override void Tick(in TickContext context)
        {
        }
    }

    [Fact]
    public void The_slowest_instance_of_the_last_tick_is_named_and_between_ticks_none_is_in_its_tick()
    {
        var graph = new PluginGraph();
        graph.Add(new Idle("first"));
        graph.Add(new Busy("busy", System.Diagnostics.Stopwatch.Frequency / 500)); // 2 ms
        graph.Add(new Idle("last"));
        var program = graph.Compile();
        Assert.Null(program.Profile.SlowestOfLastTick());
        Assert.Equal("loop", program.Profile.Culprit(0)); // before any tick

        program.Start(new TickContext(0, 0, TimeSpan.Zero, TimeSpan.FromMilliseconds(1)));
        program.Tick(new TickContext(0, 0, TimeSpan.Zero, TimeSpan.FromMilliseconds(1)));

        Assert.Null(program.Profile.InTick());
        var slowest = program.Profile.SlowestOfLastTick()!.Value;
        Assert.Equal("plug-in 'busy' (Busy), the slowest of the last tick", slowest.Name);
        Assert.True(slowest.Ms >= 2, $"{slowest.Ms} ms");
        Assert.Equal(slowest.Name, program.Profile.Culprit(1)); // it took a loop period or more
        Assert.Equal("loop", program.Profile.Culprit(1e6)); // shorter than the threshold: the loop is between ticks
    }

    [Fact]
    public void A_tick_that_never_returns_is_named_while_it_runs_and_a_bounded_stop_leaves_the_graph_unstopped()
    {
        var graph = new PluginGraph();
        var stuck = new Stuck("stuck", from: 5);
        graph.Add(new Idle("before"));
        graph.Add(stuck);
        var program = graph.Compile();
        using var loop = new ControlLoop(program, TimeProvider.System, 1000);
        loop.Start();
        try
        {
            // Not "until something is in its tick": the earlier ticks pass through 'before' and 'stuck' too, and
            // between two of them nothing is (a full run read null right after such a moment).
            Assert.True(stuck.Entered.Wait(TimeSpan.FromSeconds(20)), "the stuck tick never began");
            var inTick = program.Profile.InTick()!.Value;
            Assert.Equal("plug-in 'stuck' (Stuck), in its tick", inTick.Name);
            Assert.Equal(inTick.Name, program.Profile.Culprit(1e6)); // in its tick: named whatever the threshold

            Assert.False(loop.Stop(TimeSpan.FromMilliseconds(50))); // the thread is still in the tick
            Assert.False(stuck.Stopped); // a plug-in is not stopped while its tick runs
        }
        finally
        {
            stuck.Release.Set();
        }

        Assert.True(loop.Stop(TimeSpan.FromSeconds(20)));
        Assert.True(stuck.Stopped);
        Assert.Null(program.Profile.InTick());
    }
}
