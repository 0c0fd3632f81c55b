using RobotControl.Host.Session;
using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;
using RobotControl.Simulation.Time;

namespace RobotControl.Host.Tests.Session;

public sealed class VirtualScheduleTests
{
    /// <summary>A bus cycle that records its steps and takes bus time like a wire: read 700 us, publish 0 us or, every third cycle, a status poll; check and the work between cycles none.</summary>
    private sealed class RecordingCycle(ManualTimeProvider busClock, List<string> log, int pollUs = 300) : IBusCycle
    {
        private int _updates;

        public bool InStep { get; private set; }

        public void Write() => Step("write", TimeSpan.Zero);

        public void Read() => Step("read", TimeSpan.FromMicroseconds(700));

        public void Publish() => Step("publish", ++_updates % 3 == 0 ? TimeSpan.FromMicroseconds(pollUs) : TimeSpan.Zero);

        public void Check() => Step("check", TimeSpan.Zero);

        public void RunBetweenCycles() => Step("between", TimeSpan.Zero);

        public int Owned { get; private set; }

        public IDisposable OwnBus()
        {
            Owned++;
            return new Released(this);
        }

        private sealed class Released(RecordingCycle cycle) : IDisposable
        {
            public void Dispose() => cycle.Owned--;
        }

        private void Step(string name, TimeSpan busTime)
        {
            InStep = true;
            log.Add($"{name}@{busClock.GetTimestamp()}");
            busClock.Advance(busTime);
            InStep = false;
        }
    }

    private sealed class Probe(string name, List<string> log) : Plugin(PluginContext.Standalone(name))
    {
        public override void Tick(in TickContext context) => log.Add($"tick@{context.Timestamp}");
    }

    [Fact]
    public void The_cycle_is_write_read_publish_check_between_and_every_tick_runs_at_its_own_instant_between_steps()
    {
        var busClock = new ManualTimeProvider();
        busClock.Advance(TimeSpan.FromMilliseconds(5)); // bring-up took bus time
        var loopClock = new ManualTimeProvider();
        var log = new List<string>();
        var cycle = new RecordingCycle(busClock, log);
        var graph = new PluginGraph();
        graph.Add(new Probe("probe", log));
        using var loop = new ControlLoop(graph.Compile(), loopClock, 1000);
        var dues = new List<long>();
        var schedule = new VirtualSchedule(cycle, busClock, loopClock, loop, 5, (l, due) =>
        {
            Assert.False(cycle.InStep, "a tick ran inside a bus step");
            Assert.Equal(due, loopClock.GetTimestamp());
            dues.Add(due);
            l.Step();
        });
        var cycles = 0;
        schedule.Run(() => cycles++);

        const long Ms = 10_000; // timestamp ticks per millisecond
        Assert.Equal(5, loop.TickCount);
        Assert.Equal([6 * Ms, 7 * Ms, 8 * Ms, 9 * Ms, 10 * Ms], dues);

        // Bus time: write 5.0, read 5.0-5.7, publish, check, work between cycles; write 5.7, read 5.7-6.4 (tick 6 fell
        // due: it runs after the read), ...; the third publish is a 0.3 ms status poll (7.1-7.4), checked at its end.
        Assert.Equal(
            [
                "write@50000", "read@50000", "publish@57000", "check@57000", "between@57000",
                "write@57000", "read@57000", "tick@60000", "publish@64000", "check@64000", "between@64000",
                "write@64000", "read@64000", "tick@70000", "publish@71000", "check@74000", "between@74000",
                "write@74000", "read@74000", "tick@80000", "publish@81000", "check@81000", "between@81000",
                "write@81000", "read@81000", "publish@88000", "check@88000", "between@88000",
                "write@88000", "read@88000", "tick@90000", "publish@95000", "check@98000", "between@98000",
                "write@98000", "read@98000", "tick@100000", "publish@105000", "check@105000",
            ],
            log);
        Assert.Equal(7, cycles);
        Assert.Equal(0, cycle.Owned); // the schedule owned the bus while it ran, and let go
    }

    [Fact]
    public void Ticks_due_during_the_publish_run_after_the_check_and_before_the_next_write()
    {
        var busClock = new ManualTimeProvider();
        var loopClock = new ManualTimeProvider();
        var log = new List<string>();
        var cycle = new RecordingCycle(busClock, log, pollUs: 1200);
        var graph = new PluginGraph();
        graph.Add(new Probe("probe", log));
        using var loop = new ControlLoop(graph.Compile(), loopClock, 1000);
        new VirtualSchedule(cycle, busClock, loopClock, loop, 3).Run();

        // The third publish is a 1.2 ms status poll (2.1-3.3 ms): the tick due at 3 ms runs after it and the check, before any write.
        Assert.Equal(
            [
                "write@0", "read@0", "publish@7000", "check@7000", "between@7000",
                "write@7000", "read@7000", "tick@10000", "publish@14000", "check@14000", "between@14000",
                "write@14000", "read@14000", "tick@20000", "publish@21000", "check@33000", "tick@30000",
            ],
            log);
        Assert.Equal(0, loop.Statistics.DeadlineMisses);
    }

    /// <summary>A plug-in whose every tick costs 3 ms on <see cref="CostNs"/> (the loop's cost clock in these tests).</summary>
    private sealed class ThreeMsTicks(List<string> log) : Plugin(PluginContext.Standalone("slow"))
    {
        public long CostNs { get; private set; }

        public override void Tick(in TickContext context)
        {
            log.Add($"tick@{context.Timestamp}");
            CostNs += 3_000_000;
        }
    }

    [Theory]
    [InlineData(VirtualTickCost.Measured)]
    [InlineData(VirtualTickCost.Free)]
    public void A_tick_s_cost_counts_against_its_period_when_measured_and_not_when_free(VirtualTickCost tickCost)
    {
        var busClock = new ManualTimeProvider();
        var loopClock = new ManualTimeProvider();
        var log = new List<string>();
        var slow = new ThreeMsTicks(log);
        var graph = new PluginGraph();
        graph.Add(slow);
        using var loop = new ControlLoop(graph.Compile(), loopClock, 1000) { CostClock = () => slow.CostNs };
        new VirtualSchedule(new RecordingCycle(busClock, log, pollUs: 0), busClock, loopClock, loop, 4, tickCost: tickCost).Run();

        var ticks = log.Where(l => l.StartsWith("tick@", StringComparison.Ordinal)).ToList();
        if (tickCost == VirtualTickCost.Free)
        {
            // Every tick at its own instant, none missed: the run is the same on any machine.
            Assert.Equal(["tick@10000", "tick@20000", "tick@30000", "tick@40000"], ticks);
            Assert.Equal(0, loop.Statistics.DeadlineMisses);
        }
        else
        {
            // The first tick starts the graph (not measured); from the second on each keeps the loop busy 3 ms: the two
            // instants due meanwhile are skipped: three measured ticks of three periods, three misses each.
            Assert.Equal(["tick@10000", "tick@20000", "tick@50000", "tick@80000"], ticks);
            Assert.Equal(9, loop.Statistics.DeadlineMisses);
        }
    }

    [Fact]
    public void Zero_ticks_runs_no_cycle()
    {
        var busClock = new ManualTimeProvider();
        var log = new List<string>();
        using var loop = new ControlLoop(new PluginGraph().Compile(), new ManualTimeProvider(), 1000);
        new VirtualSchedule(new RecordingCycle(busClock, log), busClock, new ManualTimeProvider(), loop, 0).Run();
        Assert.Empty(log);
    }
}
