using Microsoft.Extensions.Time.Testing;
using RobotControl.Plugins.Sdk;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Tests.Support;

namespace RobotControl.Runtime.Tests.Loop;

public sealed class ControlLoopTests
{
    private sealed class ClockHog(string name, FakeTimeProvider clock, long atTick) : Plugin(PluginContext.Standalone(name))
    {
        public override void Tick(in TickContext context)
        {
            if (context.Index == atTick)
            {
                clock.Advance(TimeSpan.FromMilliseconds(3.5)); // this tick "takes" 3.5 periods on the loop clock
            }
        }
    }

    /// <summary>Calls, at one tick, a generic method over value types nothing else uses: new code for the JIT, on the calling thread.</summary>
    private sealed class LateFirstCall(string name, long atTick) : Plugin(PluginContext.Standalone(name))
    {
        private readonly struct A;

        private readonly struct B;

        private readonly struct C;

        public override void Tick(in TickContext context)
        {
            if (context.Index == atTick)
            {
                _ = Fresh(default(A)).GetHashCode() + Fresh(default(B)).GetHashCode() + Fresh(default(C)).GetHashCode();
            }
        }

        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        private static T Fresh<T>(T value) => value;
    }

    [Fact]
    public void Code_first_run_after_the_first_tick_is_counted_as_compiled_on_the_loop_thread()
    {
        var graph = new PluginGraph();
        graph.Add(new LateFirstCall("late", atTick: 20));
        using var loop = new ControlLoop(graph.Compile(), TimeProvider.System, 1000);

        loop.Start();
        SpinWait.SpinUntil(() => loop.TickCount >= 40, TimeSpan.FromSeconds(30));
        loop.Stop();

        Assert.Null(loop.ThreadFailure);
        Assert.True(loop.MethodsCompiledAfterFirstTick >= 3, $"{loop.MethodsCompiledAfterFirstTick} methods");
        Assert.True(loop.CompileTimeAfterFirstTick > TimeSpan.Zero);
    }

    [Fact]
    public void Stepped_on_a_virtual_clock_the_loop_ticks_once_per_period_with_loop_time_and_no_misses()
    {
        var clock = new FakeTimeProvider();
        var graph = new PluginGraph();
        var sink = new Gain("sink");
        graph.Add(new CounterSource("src"));
        graph.Add(sink);
        graph.Connect("src.value", "sink.in");
        using var loop = new ControlLoop(graph.Compile(), clock, 1000);

        for (var i = 0; i < 100; i++)
        {
            loop.Step();
            clock.Advance(loop.Period);
        }

        Assert.Equal(100, loop.TickCount);
        Assert.Equal(100, loop.Statistics.Count);
        Assert.Equal(0, loop.Statistics.DeadlineMisses);
        Assert.Equal(Enumerable.Range(0, 100).Select(i => (double)i), sink.Seen);
        Assert.True(loop.Statistics.MedianUs > 0 && loop.Statistics.P99Us <= loop.Statistics.MaxUs);
    }

    [Fact]
    public void A_tick_that_overruns_its_period_on_the_loop_clock_counts_deadline_misses()
    {
        var clock = new FakeTimeProvider();
        var graph = new PluginGraph();
        graph.Add(new ClockHog("hog", clock, atTick: 5));
        using var loop = new ControlLoop(graph.Compile(), clock, 1000);

        for (var i = 0; i < 10; i++)
        {
            loop.Step();
            clock.Advance(TimeSpan.FromTicks(Math.Max(0, loop.NextDueTimestamp - clock.GetTimestamp())));
        }

        Assert.Equal(3, loop.Statistics.DeadlineMisses); // ends 2.5 periods late: this tick plus two skipped slots
    }

    [Fact]
    public void On_its_own_thread_the_loop_runs_at_its_rate_on_the_system_clock()
    {
        var graph = new PluginGraph();
        graph.Add(new CounterSource("src"));
        using var loop = new ControlLoop(graph.Compile(), TimeProvider.System, 1000);

        var begin = TimeProvider.System.GetTimestamp();
        loop.Start();
        SpinWait.SpinUntil(() => loop.TickCount >= 100, TimeSpan.FromSeconds(30));
        loop.Stop();
        var periods = TimeProvider.System.GetElapsedTime(begin).TotalMilliseconds;

        // Other work shares this machine's cores, so the thread may be starved and ticks skipped (counted as missed):
        // what must hold is that it makes progress and never runs ahead of the system clock, not a tick count in a
        // fixed time.
        Assert.Null(loop.ThreadFailure);
        Assert.True(loop.TickCount >= 100, $"only {loop.TickCount} ticks in {periods:F0} ms");
        Assert.True(loop.TickCount <= periods + 1, $"{loop.TickCount} ticks in {periods:F0} periods: ahead of the clock");
    }
}
