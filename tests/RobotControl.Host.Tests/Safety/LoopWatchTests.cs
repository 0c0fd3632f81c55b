using RobotControl.Bus.Transports.Serial;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Plugins.Sdk.Settings;
using RobotControl.Robot.States;
using RobotControl.Runtime.Discovery;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Host.Tests.Safety;

/// <summary>The test plug-ins' way of being slow: CPU time, which the virtual schedule counts, not wall time.</summary>
/// <para>
/// A thread that <see cref="Charge"/>s a loop also adds each spend to a cost clock that only the plug-ins move, so the
/// misses are exactly the plug-ins' (on a virtual machine a thread's CPU time also holds time the host held its virtual
/// CPU, and the rest of the graph costs a little too).
/// </para>
internal static class Cpu
{
    [ThreadStatic]
    private static long? t_chargedNs;

    /// <summary>From now on, on this thread, spending only moves <paramref name="loop"/>'s cost clock.</summary>
    public static void Charge(RobotControl.Runtime.Loop.ControlLoop loop)
    {
        t_chargedNs = 0;
        loop.CostClock = () => t_chargedNs ?? 0;
    }

    /// <summary>Spins until the calling thread has spent <paramref name="ms"/> more of CPU time (the supervisor names the plug-in by its time), and adds it to the charged cost clock.</summary>
    public static void Spend(double ms)
    {
        if (t_chargedNs is { } charged)
        {
            t_chargedNs = charged + (long)(ms * 1e6);
        }

        var until = ThreadCpuClock.NowNs() + (long)(ms * 1e6);
        while (ThreadCpuClock.NowNs() < until)
        {
        }
    }
}

/// <summary>Settings of the test plug-ins: from which tick they misbehave, and how long a slow one spends per tick.</summary>
public sealed record MisbehaviourSettings : PluginSettings
{
    /// <summary>First tick that misbehaves.</summary>
    [Setting("first tick that misbehaves", Minimum = 0, Maximum = 1e9)]
    public double FromTick { get; init; }

    /// <summary>CPU time per tick, ms (cpu_burner).</summary>
    [Setting("CPU time per tick, ms", Minimum = 0, Maximum = 10_000)]
    public double Ms { get; init; }
}

/// <summary>Spends <see cref="MisbehaviourSettings.Ms"/> of its thread's CPU time in every tick from <see cref="MisbehaviourSettings.FromTick"/>.</summary>
[PluginType("cpu_burner", Description = "test: a slow plug-in")]
public sealed class CpuBurnerPlugin : Plugin<MisbehaviourSettings>
{
    public CpuBurnerPlugin(MisbehaviourSettings settings, PluginContext context)
        : base(settings, context) => DeclareOutput("x", SafeValue.Zero, "", "nothing");

    public override void Tick(in TickContext context)
    {
        if (context.Index < Settings.FromTick)
        {
            return;
        }

        Cpu.Spend(Settings.Ms);
    }
}

/// <summary>Settings of <see cref="RandomCostPlugin"/>.</summary>
public sealed record RandomCostSettings : PluginSettings
{
    /// <summary>Seed of the costs.</summary>
    [Setting("seed of the costs", Minimum = 0, Maximum = 1e6)]
    public double Seed { get; init; }

    /// <summary>Longest cost drawn, ms.</summary>
    [Setting("longest cost drawn, ms", Minimum = 2, Maximum = 100)]
    public double MaxMs { get; init; } = 5;
}

/// <summary>A tick in twenty (seeded) spends a whole number of milliseconds of CPU time, 2 to <see cref="RandomCostSettings.MaxMs"/>; the others nothing.</summary>
[PluginType("random_cost", Description = "test: random tick costs")]
public sealed class RandomCostPlugin : Plugin<RandomCostSettings>
{
    private readonly Random _random;

    public RandomCostPlugin(RandomCostSettings settings, PluginContext context)
        : base(settings, context)
    {
        _random = new Random((int)settings.Seed);
        DeclareOutput("x", SafeValue.Zero, "", "nothing");
    }

    /// <summary>Every slow tick and its cost, ms (sized up front: a tick allocates nothing).</summary>
    public List<(long Tick, int Ms)> SlowTicks { get; } = new(10_000);

    public override void Tick(in TickContext context)
    {
        if (context.Index == 0 || _random.Next(20) != 0)
        {
            return;
        }

        var ms = _random.Next(2, (int)Settings.MaxMs + 1);
        SlowTicks.Add((context.Index, ms));
        Cpu.Spend(ms);
    }
}

/// <summary>Throws in every tick from <see cref="MisbehaviourSettings.FromTick"/>; its output drives a jaw of the robot.</summary>
[PluginType("thrower", Description = "test: a plug-in that faults")]
public sealed class ThrowerPlugin : Plugin<MisbehaviourSettings>
{
    public ThrowerPlugin(MisbehaviourSettings settings, PluginContext context)
        : base(settings, context) => DeclareOutput("jaw", SafeValue.HoldLastFinite, "rad", "a jaw setpoint");

    public override void Tick(in TickContext context)
    {
        if (context.Index >= Settings.FromTick)
        {
            throw new InvalidOperationException("the device went away");
        }
    }
}

/// <summary>Blocks in its tick from <see cref="MisbehaviourSettings.FromTick"/> until the test releases it (a tick that never returns).</summary>
[PluginType("stuck", Description = "test: a tick that never returns")]
public sealed class StuckPlugin : Plugin<MisbehaviourSettings>
{
    public static readonly ManualResetEventSlim Release = new();

    public StuckPlugin(MisbehaviourSettings settings, PluginContext context)
        : base(settings, context) => DeclareOutput("x", SafeValue.Zero, "", "nothing");

    public override void Tick(in TickContext context)
    {
        if (context.Index >= Settings.FromTick)
        {
            Release.Wait();
        }
    }
}

/// <summary>
/// The loop watched from outside (issue: a loop that overruns or hangs is a fault): a slow plug-in on the virtual
/// robot trips the supervisor as it would on the wall clock, named; a plug-in fault upstream of the robot is a trip
/// naming it; a tick that never returns, on real threads over a pseudo-terminal, takes the motors off at the modules'
/// torque-off stage, and a stop then switches them off and reads them back before giving up on the loop.
/// </summary>
public sealed class LoopWatchTests : IDisposable
{
    private readonly DirectoryInfo _dir = Directory.CreateTempSubdirectory("rcloopwatch");

    private static PluginCatalog Catalog() => PluginCatalog.FromAssemblies(typeof(LoopWatchTests).Assembly);

    private string Graph(string instance, string type, string settings, string wires = "[]", string transport = "virtual")
    {
        var robot = RepositoryPaths.Robot("lb-1.0.json").Replace('\\', '/');
        var path = Path.Combine(_dir.FullName, $"{instance}.json");
        File.WriteAllText(path, $$"""
            {
              "schema": "robotcontrol/graph/1",
              "robot": "{{robot}}",
              "transport": "{{transport}}",
              "loop_rate_hz": 1000,
              "instances": [ { "name": "{{instance}}", "type": "{{type}}", "settings": {{settings}} } ],
              "wires": {{wires}}
            }
            """);
        return path;
    }

    [Fact]
    public void On_the_virtual_robot_a_tick_that_costs_more_than_its_period_is_missed_and_a_slow_plug_in_trips_the_supervisor_named()
    {
        Assert.True(ThreadCpuClock.Available);
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graph("slow", "cpu_burner", """{ "from_tick": 200, "ms": 30 }""") }, Catalog());
        session.Supervisor.PedalDown("pedal");
        session.RunVirtual(400);

        // 30 ms of CPU per tick at 1 kHz: each slow tick keeps the loop busy for 30 ms of virtual time (skipped ticks are
        // misses too), and the supervisor sees the loop fall behind as it would with real threads.
        Assert.True(session.Loop.Statistics.DeadlineMisses >= 29, $"{session.Loop.Statistics.DeadlineMisses} misses");
        var trip = Assert.Single(session.Supervisor.Trips);
        Assert.Equal((SafetyCheck.DeadlineMiss, "plug-in 'slow' (CpuBurnerPlugin), the slowest of the last tick", true), (trip.Check, trip.Joint, trip.Soft));
        Assert.True(trip.Measured > 10, $"{trip.Measured} ms"); // the stall limit: 10 loop periods
        Assert.Equal(RunLevel.PedalUp, session.Supervisor.Level);
    }

    [Theory]
    [InlineData(1, 5)]
    [InlineData(2, 5)]
    [InlineData(3, 9)]
    [InlineData(4, 14)]
    [InlineData(5, 14)]
    public void Random_tick_costs_on_the_virtual_clock_are_missed_by_their_length_and_trip_only_past_the_stall_limit(int seed, int maxMs)
    {
        var graph = Graph($"costs{seed}", "random_cost", $$"""{ "seed": {{seed}}, "max_ms": {{maxMs}} }""");
        using var session = RobotSession.Open(new SessionOptions { GraphPath = graph }, Catalog());
        Cpu.Charge(session.Loop); // the plug-in's costs alone, exactly
        session.Supervisor.PedalDown("pedal");
        session.RunVirtual(400);

        // A tick costing k ms ends after its deadline and overruns k - 1 more slots: k misses, as the loop counts them
        // on its own thread, and the instants it overran are skipped.
        var slow = session.Graph.Program.Order.OfType<RandomCostPlugin>().Single().SlowTicks.Select(s => s.Ms).ToList();
        Assert.NotEmpty(slow);
        Assert.Equal(slow.Sum(), session.Loop.Statistics.DeadlineMisses);
        Assert.Equal(400, session.Loop.TickCount); // the slots overrun were skipped, not counted as ticks

        // The supervisor trips (soft, naming the plug-in) when a tick kept the loop from ticking for longer than the
        // stall limit (10 loop periods) while it drove the arms, and not for shorter ones.
        var longest = slow.Max();
        if (longest >= 11)
        {
            var trip = session.Supervisor.Trips[0];
            Assert.Equal((SafetyCheck.DeadlineMiss, $"plug-in 'costs{seed}' (RandomCostPlugin), the slowest of the last tick", true), (trip.Check, trip.Joint, trip.Soft));
        }
        else if (longest <= 8)
        {
            Assert.Empty(session.Supervisor.Trips);
        }
    }

    [Fact]
    public void On_the_virtual_robot_ticks_within_their_period_are_not_missed()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graph("light", "cpu_burner", """{ "from_tick": 0, "ms": 0.9 }""") }, Catalog());
        Cpu.Charge(session.Loop); // 0.9 ms of a 1 ms period, exactly
        session.Supervisor.PedalDown("pedal");
        session.RunVirtual(300);
        Assert.Equal(0, session.Loop.Statistics.DeadlineMisses);
        Assert.Empty(session.Supervisor.Trips);
    }

    [Fact]
    public void A_plug_in_fault_upstream_of_the_robot_is_a_trip_naming_it_and_the_console_cannot_jog()
    {
        var graph = Graph("gripper", "thrower", """{ "from_tick": 50 }""", """[ { "from": "gripper.jaw", "to": "robot.right.jaw" } ]""");
        using var session = RobotSession.Open(new SessionOptions { GraphPath = graph }, Catalog());
        session.Supervisor.PedalDown("pedal");
        session.RunVirtual(200);

        var trip = Assert.Single(session.Supervisor.Trips);
        Assert.Equal((SafetyCheck.PluginFault, "plug-in 'gripper'", SafeState.Hold, false), (trip.Check, trip.Joint, trip.Action, trip.Soft));
        Assert.Equal(RunLevel.EStop, session.Supervisor.Level); // motion (a jog included) needs PEDAL_DOWN
        Assert.Matches(@"^plug-in 'gripper' faulted at tick 50 \(tick failed: InvalidOperationException: the device went away\); it is no longer ticked and the arms hold$", session.Supervisor.History[^1].Reason);
        Assert.True(session.Node.Holding);
    }

    [Fact]
    public void A_tick_that_never_returns_on_real_threads_trips_naming_the_plug_in_motors_off_and_the_stop_reads_them_back()
    {
        using var pty = PseudoTerminal.Create();
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider(), new VirtualRobotOptions { InitialJointsRad = [[0, 0, 0, 1.0, 0], [0, 0, 0, 1.5, 0]] });
        using var serving = new CancellationTokenSource();
        var server = new Thread(() => sim.Serve(pty, serving.Token)) { IsBackground = true };
        server.Start();
        StuckPlugin.Release.Reset();
        try
        {
            var graph = Graph("stuck", "stuck", """{ "from_tick": 100 }""", transport: $"serial:{pty.SlavePath}?baud=1000000");
            using var session = RobotSession.Open(new SessionOptions { GraphPath = graph, Virtual = false }, Catalog());
            session.StartRealtime();
            var waited = System.Diagnostics.Stopwatch.StartNew();
            while (session.Supervisor.Level != RunLevel.EStop && waited.Elapsed < TimeSpan.FromSeconds(30))
            {
                Thread.Sleep(10);
            }

            // The loop is watched from outside: at PEDAL_UP, soft at the stall limit, then motors off at the modules'
            // torque-off stage (500 ms), each naming the plug-in the loop waits for.
            Assert.Equal(RunLevel.EStop, session.Supervisor.Level);
            var last = session.Supervisor.Trips[^1];
            Assert.Equal((SafetyCheck.DeadlineMiss, "plug-in 'stuck' (StuckPlugin), in its tick", SafeState.TorqueOff), (last.Check, last.Joint, last.Action));
            Assert.True(last.Measured >= 500, $"{last.Measured} ms");

            var stop = session.Stop();
            Assert.True(stop.TorqueOff, stop.Summary); // read back, though the loop's thread never came back
            Assert.NotNull(stop.AfterRequest);
            Assert.Matches(@"^the control loop did not end: plug-in 'stuck' \(StuckPlugin\), in its tick for \d+\.\d s; its plug-ins were not stopped$", stop.LoopHung);
            Assert.NotEqual(RobotState.Enabled, session.Robot.State);
        }
        finally
        {
            StuckPlugin.Release.Set();
            serving.Cancel();
            server.Join(); // before the virtual robot is disposed under it
        }
    }

    public void Dispose() => _dir.Delete(recursive: true);
}
