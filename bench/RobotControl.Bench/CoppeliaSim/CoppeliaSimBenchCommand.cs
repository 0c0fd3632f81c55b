using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.CoppeliaSim;
using RobotControl.CoppeliaSim.Tests;
using RobotControl.Definitions.Loading;
using RobotControl.Plugins.CoppeliaSim;
using RobotControl.Plugins.CoppeliaSim.Tests;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;

namespace RobotControl.Bench.CoppeliaSim;

/// <summary>
/// <c>coppeliasim [--robot hardware/robots/lb-1.0.json] [--seconds 3] [--ticks-per-step 10] [--repeats 3] [--json out.json]</c>:
/// (1) remote API round trips per second on loopback (<c>sim.getJointPosition</c> against the test suite's fake
/// CoppeliaSim server); (2) a real-time 1 kHz loop with the bridge in stepped mode, one simulator step per N ticks,
/// against the same loop without the bridge: tick median/p99/max, deadline misses, ticks per step.
/// </summary>
internal sealed class CoppeliaSimBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true };

    public string Name => "coppeliasim";

    public string Description => "CoppeliaSim bridge: remote API round trips/s on loopback, loop tick p99 with stepping on vs without the bridge";

    public int Run(string[] args)
    {
        var robotPath = Path.GetFullPath(BenchArgs.Value(args, "--robot") ?? "hardware/robots/lb-1.0.json");
        var seconds = double.Parse(BenchArgs.Value(args, "--seconds") ?? "3", CultureInfo.InvariantCulture);
        var ticksPerStep = int.Parse(BenchArgs.Value(args, "--ticks-per-step") ?? "10", CultureInfo.InvariantCulture);
        var repeats = int.Parse(BenchArgs.Value(args, "--repeats") ?? "3", CultureInfo.InvariantCulture);
        var robot = RobotLoader.Load(robotPath);
        var paths = robot.Arms.SelectMany(a => robot.Joints.Select(j => $"/LB1/{a.Name}_{j.Name}")).ToList();

        var roundTrips = Enumerable.Range(0, repeats).Select(_ => RoundTripsPerSecond(paths, seconds)).ToList();
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"round trips/s (loopback, fake server): {string.Join(", ", roundTrips.Select(r => r.ToString("F0", CultureInfo.InvariantCulture)))}; median {Median(roundTrips):F0}"));

        var loops = new List<object>();
        for (var r = 0; r < repeats; r++)
        {
            var without = LoopRun(robotPath, robot, paths, seconds, null);
            var with = LoopRun(robotPath, robot, paths, seconds, ticksPerStep);
            loops.Add(new { without, with });
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"loop without bridge: p50 {without.P50Us:F1} us, p99 {without.P99Us:F1} us, max {without.MaxUs:F0} us, misses {without.Misses}"));
            Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"loop with bridge (stepping, 1 step per {ticksPerStep} ticks): p50 {with.P50Us:F1} us, p99 {with.P99Us:F1} us, max {with.MaxUs:F0} us, misses {with.Misses}, {with.Ticks} ticks, {with.Steps} steps ({with.TicksPerStep:F2} ticks/step)"));
        }

        var json = BenchArgs.Value(args, "--json");
        if (json is not null)
        {
            File.WriteAllText(json, JsonSerializer.Serialize(new { robot = robot.Name, seconds, ticksPerStep, roundTripsPerSecond = roundTrips, roundTripsMedian = Median(roundTrips), loops }, JsonOptions));
        }

        return 0;
    }

    private static double RoundTripsPerSecond(List<string> paths, double seconds)
    {
        using var server = new FakeCoppeliaSim(paths);
        using var client = new RemoteApiClient(server.Endpoint, TimeSpan.FromSeconds(1));
        var sim = new SimApi(client);
        var handle = sim.GetObject(paths[0]);
        var watch = Stopwatch.StartNew();
        var before = client.RoundTrips;
        while (watch.Elapsed.TotalSeconds < seconds)
        {
            sim.GetJointPosition(handle);
        }

        return (client.RoundTrips - before) / watch.Elapsed.TotalSeconds;
    }

    private static LoopResult LoopRun(string robotPath, Definitions.Model.RobotDefinition robot, List<string> paths, double seconds, int? ticksPerStep)
    {
        using var server = new FakeCoppeliaSim(paths) { WaitsPerStep = 1 };
        var instances = ticksPerStep is { } n
            ? $$"""[ { "name": "sim", "type": "coppeliasim", "settings": { "endpoint": "{{server.Endpoint}}", "stepping": true, "ticks_per_step": {{n}} } } ]"""
            : "[]";
        var json = $$"""{ "schema": "robotcontrol/graph/1", "robot": "{{robotPath}}", "loop_rate_hz": 1000, "instances": {{instances}}, "wires": [] }""";
        var catalog = PluginCatalog.FromAssemblies(typeof(CoppeliaSimPlugin).Assembly);
        var loaded = GraphFile.LoadFromText(json, robotPath, catalog, TimeProvider.System);
        loaded.RobotNode!.Attach(new HeldRobotPort(robot));
        var plugin = loaded.Program.Order.OfType<CoppeliaSimPlugin>().SingleOrDefault();
        using var loop = new ControlLoop(loaded.Program, TimeProvider.System, loaded.Document.LoopRateHz);
        loop.Start();
        Thread.Sleep(TimeSpan.FromSeconds(seconds));
        loop.Stop();
        var s = loop.Statistics;
        var steps = plugin?.Steps ?? 0;
        return new LoopResult(s.Percentile(0.5), s.P99Us, s.MaxUs, s.DeadlineMisses, loop.TickCount, steps, steps > 0 ? (double)loop.TickCount / steps : 0);
    }

    private static double Median(List<double> values)
    {
        var sorted = values.Order().ToList();
        return sorted.Count % 2 == 1 ? sorted[sorted.Count / 2] : 0.5 * (sorted[(sorted.Count / 2) - 1] + sorted[sorted.Count / 2]);
    }


    private sealed record LoopResult(double P50Us, double P99Us, double MaxUs, long Misses, long Ticks, long Steps, double TicksPerStep);
}
