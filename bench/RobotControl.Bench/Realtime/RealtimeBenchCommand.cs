using System.Diagnostics;
using System.Globalization;
using System.Runtime;
using System.Text.Json;
using RobotControl.Cli;
using RobotControl.Definitions.Model;
using RobotControl.Host.Harness;
using RobotControl.Host.Realtime;
using RobotControl.Host.Safety;

namespace RobotControl.Bench.Realtime;

/// <summary>
/// <c>realtime [--graph graphs/teleop-lb.json] [--robot hardware/robots/lb-1.0.json] [--seconds 600]
/// [--scenarios idle,idle-sll,busy] [--rt-priority 0] [--sim-rt-priority 0] [--cpu N] [--floor-seconds 10] [--floor-during no] [--cpu-latency hold] [--baud 3000000] [--out file.json]</c>: the shipped teleop graph on the
/// wall clock, the 1 kHz loop and the bus on their own threads, the virtual robot (real firmware) in another process
/// behind a pty (<c>robotctl bus-sim --pty</c>, a fresh one per scenario). Per scenario: deadline misses, tick start
/// jitter p50/p99/p99.9/max, bus cycle period distribution, late replies, CRC errors, timeouts, retries, safety trips,
/// tracking RMS/max next to the virtual-clock run of the same graph, and bytes allocated per tick. Scenarios:
/// <c>idle</c> (default GC latency mode), <c>idle-sll</c> (<see cref="GCLatencyMode.SustainedLowLatency"/>),
/// <c>busy</c> (SustainedLowLatency, one core kept busy by <c>stress-ng --cpu 1</c>), <c>record</c> (as idle-sll, the
/// session recorded to MCAP, <c>--record</c>, zstd; alternate it with idle-sll to compare side by side). Before each scenario,
/// <see cref="PlatformFloor"/> measures what the machine allows any SCHED_FIFO thread (cyclictest), and the hypervisor's
/// steal is counted over the run.
/// </summary>
internal sealed class RealtimeBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower, NumberHandling = System.Text.Json.Serialization.JsonNumberHandling.AllowNamedFloatingPointLiterals };

    public string Name => "realtime";

    public string Description => "Teleop graph on the wall clock against the virtual robot in another process behind a pty: misses, jitter, bus periods, late replies.";

    private static readonly string[] Options = ["--graph", "--robot", "--seconds", "--scenarios", "--rt-priority", "--sim-rt-priority", "--cpu", "--floor-seconds", "--floor-during", "--cpu-latency", "--baud", "--out"];

    public int Run(string[] args)
    {
        var unknown = args.Where((a, i) => i % 2 == 0).FirstOrDefault(a => !Options.Contains(a));
        if (unknown is not null || args.Length % 2 != 0)
        {
            Console.Error.WriteLine($"realtime: {(unknown is null ? $"{args[^1]} needs a value" : $"unknown option '{unknown}'")}; options: {string.Join(' ', Options)} (each with a value)");
            return 2;
        }

        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var robot = BenchArgs.Value(args, "--robot") ?? "hardware/robots/lb-1.0.json";
        var seconds = double.Parse(BenchArgs.Value(args, "--seconds") ?? "600", CultureInfo.InvariantCulture);
        var scenarios = (BenchArgs.Value(args, "--scenarios") ?? "idle,idle-sll,busy").Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        var priority = int.Parse(BenchArgs.Value(args, "--rt-priority") ?? "0", CultureInfo.InvariantCulture);
        var simPriority = int.Parse(BenchArgs.Value(args, "--sim-rt-priority") ?? "0", CultureInfo.InvariantCulture);
        int? cpu = BenchArgs.Value(args, "--cpu") is { } c ? int.Parse(c, CultureInfo.InvariantCulture) : null;
        var outFile = BenchArgs.Value(args, "--out");
        int? baud = BenchArgs.Value(args, "--baud") is { } b ? int.Parse(b, CultureInfo.InvariantCulture) : null;
        var floorDuring = BenchArgs.Value(args, "--floor-during") ?? "no";
        var cpuLatency = BenchArgs.Value(args, "--cpu-latency") ?? "hold";
        var floorTime = TimeSpan.FromSeconds(double.Parse(BenchArgs.Value(args, "--floor-seconds") ?? "10", CultureInfo.InvariantCulture));
        if (!double.IsFinite(seconds) || seconds is < 1 or > 86_400 || scenarios.Any(s => s is not ("idle" or "idle-sll" or "busy" or "record"))
            || floorTime < TimeSpan.Zero || floorTime > TimeSpan.FromHours(1) || floorDuring is not ("yes" or "no") || cpuLatency is not ("hold" or "free"))
        {
            Console.Error.WriteLine("realtime: --seconds 1..86400, --scenarios from idle, idle-sll, busy, record, --floor-seconds 0..3600, --floor-during yes|no, --cpu-latency hold|free");
            return 2;
        }

        // Ctrl+C ends the scenario that runs (its simulator and load processes killed) and writes what was measured.
        using var interrupt = new CancellationTokenSource();
        ConsoleCancelEventHandler cancel = (_, e) =>
        {
            e.Cancel = true;
            Console.Error.WriteLine("realtime: interrupted: ending the scenario, stopping the simulator");
            interrupt.Cancel();
        };
        Console.CancelKeyPress += cancel;
        try
        {
            return Run(graph, robot, seconds, scenarios, new RealtimeThreads(priority, cpu) { HoldCpuLatency = cpuLatency == "hold" }, new SimSettings(simPriority, baud), new FloorSettings(floorTime, floorDuring == "yes"), outFile, interrupt.Token);
        }
        finally
        {
            Console.CancelKeyPress -= cancel;
        }
    }

    private static int Run(string graph, string robot, double seconds, string[] scenarios, RealtimeThreads threads, SimSettings sim, FloorSettings floor, string? outFile, CancellationToken interrupt)
    {
        var duration = TimeSpan.FromSeconds(seconds);
        var catalog = ShippedPlugins.Catalog();
        Console.WriteLine($"virtual-clock reference: {graph}, {seconds} s");
        var reference = HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = duration, Stop = interrupt }, catalog);
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  tracking rms {reference.TrackingRmsMm:F3} mm, max {reference.TrackingMaxMm:F3} mm, {reference.DeadlineMisses} misses"));
        var results = new List<ScenarioResult>();
        var failures = new List<string>();
        foreach (var name in scenarios.TakeWhile(_ => !interrupt.IsCancellationRequested))
        {
            Console.WriteLine($"scenario {name}: {seconds} s on the wall clock (load average {LoadAverage()})");
            try
            {
                var result = RunScenario(name, graph, robot, duration, threads, sim, floor, reference, interrupt);
                results.Add(result);
                Console.WriteLine(result.Line());
            }
            catch (Exception ex) when (ex is IOException or InvalidOperationException)
            {
                Console.WriteLine($"  did not run: {ex.Message}");
                failures.Add($"{name}: {ex.Message}");
            }
        }

        if (outFile is not null)
        {
            File.WriteAllText(outFile, JsonSerializer.Serialize(new
            {
                graph,
                robot,
                seconds,
                transportBaud = sim.Baud,
                processors = Environment.ProcessorCount,
                serverGc = GCSettings.IsServerGC,
                @virtual = new { trackingRmsMm = reference.TrackingRmsMm, trackingMaxMm = reference.TrackingMaxMm, deadlineMisses = reference.DeadlineMisses },
                interrupted = interrupt.IsCancellationRequested,
                scenarios = results,
                failures,
            }, JsonOptions));
            Console.WriteLine($"wrote {outFile}");
        }

        return interrupt.IsCancellationRequested ? 130 : failures.Count == 0 ? 0 : 1;
    }

    private static ScenarioResult RunScenario(string name, string graph, string robot, TimeSpan duration, RealtimeThreads threads, SimSettings simSettings, FloorSettings floorSettings, RunReport reference, CancellationToken interrupt)
    {
        var (sim, transport) = ChildProcess.StartBusSim(robot, simSettings.FifoPriority, simSettings.Baud);
        using (sim)
        {
            string? loadProblem = null;
            using var load = name == "busy" ? ChildProcess.StartCpuLoad(duration + TimeSpan.FromSeconds(10), out loadProblem) : null;
            var gc = name == "idle" ? GCLatencyMode.Interactive : GCLatencyMode.SustainedLowLatency; // set by the run, restored after it
            // The machine's own floor, in the same conditions (simulator idle, load running), just before the run.
            var floor = floorSettings.Before > TimeSpan.Zero ? PlatformFloor.Measure(floorSettings.Before, threads.Priority) : null;
            // And, asked for, alongside the run: the same thread waking every 1 ms while the loop and the bus run.
            // It runs 3 s past the run, so that reading its histogram is not counted as the run's allocation.
            var floorDuring = floorSettings.During ? Task.Run(() => PlatformFloor.Measure(duration + TimeSpan.FromSeconds(3), threads.Priority)) : null;
            var stealStart = PlatformFloor.StealTicks();
            var loadStart = LoadAverage();
            CycleTimesLink? cycles = null;
            var gen0 = GC.CollectionCount(0);
            var gen2 = GC.CollectionCount(2);
            long allocStart = 0, allocStartAt = 0, allocEnd = 0, allocEndAt = 0;
            double lagP50 = 0, lagP99 = 0, lagP999 = 0, lagMax = 0;
            var tickTime = new Quantiles(0, 0, 0, 0);
            var pauseStart = GC.GetTotalPauseDuration();
            var recordDir = name == "record" ? Directory.CreateTempSubdirectory("rc-bench-rt-rec-") : null;
            var record = recordDir is null ? null : new Host.Recording.RecordingOptions { Path = Path.Combine(recordDir.FullName, "session.mcap") };
            var report = HeadlessRun.RunRealTime(
                new RunOptions { GraphPath = graph, Virtual = false, Transport = transport, Duration = duration, ContinueOnFault = true, Threads = threads, RealtimeGcLatency = gc, Stop = interrupt, Record = record },
                ShippedPlugins.Catalog(),
                new VirtualRunHooks
                {
                    WrapLink = (link, _) => cycles = new CycleTimesLink(link, (int)(duration.TotalSeconds * 2_000) + 10_000, () => (allocStart, allocStartAt) = (GC.GetTotalAllocatedBytes(), Stopwatch.GetTimestamp())),
                    AfterRun = session =>
                    {
                        (allocEnd, allocEndAt) = (GC.GetTotalAllocatedBytes(), Stopwatch.GetTimestamp());
                        var s = session.Loop.Statistics;
                        (lagP50, lagP99, lagP999, lagMax) = (s.StartLagPercentile(0.5), s.StartLagPercentile(0.99), s.StartLagPercentile(0.999), s.StartLagMaxUs);
                        tickTime = new Quantiles(s.Percentile(0.5), s.Percentile(0.99), s.Percentile(0.999), s.MaxUs);
                    },
                });
            var stealMs = (PlatformFloor.StealTicks() - stealStart) * CpuTimes.MillisecondsPerTick;
            if (report.Recording is { } recording)
            {
                Console.WriteLine($"scenario {name}: {recording}");
            }

            recordDir?.Delete(recursive: true);
            var simEnd = sim.Stop(TimeSpan.FromSeconds(10)) ?? "the simulator did not stop on SIGTERM: killed";
            var periods = Periods(cycles!.Starts);
            var allocSeconds = (allocEndAt - allocStartAt) / (double)Stopwatch.Frequency;
            var bytesPerSecond = allocStart > 0 && allocSeconds > 0 ? (allocEnd - allocStart) / allocSeconds : double.NaN;
            var safety = report.Safety;
            return new ScenarioResult(
                name,
                gc.ToString(),
                report.Scheduling ?? threads.Outcome,
                loadProblem,
                loadStart,
                LoadAverage(),
                report.Ticks,
                report.DeadlineMisses,
                report.Ticks == 0 ? 0 : report.DeadlineMisses / (double)report.Ticks,
                new Quantiles(lagP50, lagP99, lagP999, lagMax),
                tickTime,
                periods.Length == 0 ? new Quantiles(0, 0, 0, 0) : new Quantiles(Quantile(periods, 0.5), Quantile(periods, 0.99), Quantile(periods, 0.999), periods[^1]),
                periods.Length == 0 ? 0 : periods.Length / (periods.Sum() * 1e-6),
                report.Bus.LateReplies,
                report.Bus.CrcErrors,
                report.Bus.Timeouts,
                report.Bus.Retries,
                report.Faults.Count(f => f.Message.Contains("watchdog", StringComparison.OrdinalIgnoreCase)),
                safety is null ? [] : [.. safety.Trips.Select(t => $"{t.Check.Name()} {t.Joint} at {t.TimeSeconds:F3} s: {t.Measured:G4} {t.Unit}{(t.Soft ? " (soft)" : string.Empty)}".Replace("  ", " ", StringComparison.Ordinal))],
                safety?.Trips.Count(t => t.Soft) ?? 0,
                safety?.Trips.Count(t => !t.Soft) ?? 0,
                safety is null || report.DurationSeconds <= 0 ? 0 : safety.PedalDownSeconds / report.DurationSeconds,
                safety?.ReEngagements ?? 0,
                report.TrackingRmsMm,
                report.TrackingMaxMm,
                reference.TrackingRmsMm == 0 ? double.NaN : report.TrackingRmsMm / reference.TrackingRmsMm,
                bytesPerSecond / 1000.0,
                bytesPerSecond / (periods.Length == 0 ? double.NaN : periods.Length / (periods.Sum() * 1e-6)),
                GC.CollectionCount(0) - gen0,
                GC.CollectionCount(2) - gen2,
                (GC.GetTotalPauseDuration() - pauseStart).TotalMilliseconds,
                MaxPauseMs(),
                report.Stop?.TorqueOff ?? false,
                report.Stop is not { } stop ? ["no stop check"] : [.. stop.TorqueOn.Select(m => $"torque on: {m}"), .. stop.Unreachable.Select(m => $"no answer: {m}")],
                floor,
                floorDuring?.GetAwaiter().GetResult(),
                stealMs,
                simEnd,
                report.Compiled?.Summary ?? "not measured",
                StartupGap.Longest(cycles.Starts, cycles.Trace, 3));
        }
    }

    /// <summary>The longest pause of the last collection of each kind (ephemeral, full blocking, background), milliseconds.</summary>
    private static double MaxPauseMs() =>
        new[] { GCKind.Ephemeral, GCKind.FullBlocking, GCKind.Background }
            .Select(GC.GetGCMemoryInfo)
            .Where(i => i.Index > 0)
            .SelectMany(i => i.PauseDurations.ToArray())
            .Select(p => p.TotalMilliseconds)
            .DefaultIfEmpty(0)
            .Max();

    /// <summary>Sorted cycle periods in microseconds, from consecutive cycle starts.</summary>
    private static double[] Periods(ReadOnlySpan<long> starts)
    {
        var periods = new double[Math.Max(0, starts.Length - 1)];
        for (var i = 1; i < starts.Length; i++)
        {
            periods[i - 1] = (starts[i] - starts[i - 1]) * 1e6 / Stopwatch.Frequency;
        }

        Array.Sort(periods);
        return periods;
    }

    internal static double Quantile(double[] sorted, double q) => sorted[Math.Min(sorted.Length - 1, (int)Math.Ceiling(q * sorted.Length) - 1)];

    internal static string LoadAverage()
    {
        try
        {
            return string.Join(' ', File.ReadAllText("/proc/loadavg").Split(' ').Take(3));
        }
        catch (IOException)
        {
            return "?";
        }
    }


    /// <summary>How the simulator process runs: its SCHED_FIFO priority (0: none) and the baud its modules are commissioned at (null: the robot file's).</summary>
    private sealed record SimSettings(int FifoPriority, int? Baud);

    /// <summary>The machine's floor (cyclictest): how long before each scenario (0: not measured), and whether alongside the run too.</summary>
    private sealed record FloorSettings(TimeSpan Before, bool During);
}
