using System.Globalization;
using System.Text;
using RobotControl.Cli;
using RobotControl.Host.Harness;

namespace RobotControl.Bench.Loop;

/// <summary>
/// <c>loop [--graph graphs/teleop-lb.json] [--duration 20s] [--out docs/perf/loop.md]</c>: the two-arm teleoperation
/// graph on the virtual robot (firmware in the loop, virtual clock): per-tick cost (median, p99, max; a cold and a
/// warm run in one process), allocations per tick (GC.GetAllocatedBytesForCurrentThread around every tick after the
/// first second), latency from the Touch sample (tick time) to the end of the sync-write frame carrying the
/// setpoints on the virtual wire, and tracking error without and with injected bit errors and module resets.
/// </summary>
internal sealed class LoopBench : IBenchCommand
{
    public string Name => "loop";

    public string Description => "Control loop: tick cost, allocations, Touch->wire latency, tracking error with/without faults.";

    public int Run(string[] args)
    {
        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var duration = RunDuration.Parse(BenchArgs.Value(args, "--duration") ?? "20s");
        var outPath = BenchArgs.Value(args, "--out") ?? "docs/perf/loop.md";
        var catalog = ShippedPlugins.Catalog();
        var c = CultureInfo.InvariantCulture;

        // 1. Tick cost, allocations and latency in one run (after a cold run to warm the JIT).
        var cold = HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = duration }, catalog);
        FrameTapLink? tap = null;
        var tickTimes = new List<long>((int)(duration.TotalSeconds * 1000) + 16);
        long allocated = 0, measuredTicks = 0;
        TimeProvider? clock = null;
        var warm = HeadlessRun.RunVirtual(new RunOptions { GraphPath = graph, Duration = duration }, catalog, new VirtualRunHooks
        {
            WrapLink = (link, time) => { clock = time; return tap = new FrameTapLink(link, time); },
            AroundTick = (loop, due) =>
            {
                tickTimes.Add(due);
                var before = GC.GetAllocatedBytesForCurrentThread();
                loop.Step();
                var after = GC.GetAllocatedBytesForCurrentThread();
                if (loop.TickCount > 1000)
                {
                    allocated += after - before;
                    measuredTicks++;
                }
            },
        });
        var latencies = Latencies(tickTimes, tap!, clock!.TimestampFrequency, warm);

        // 2. Tracking error with and without faults.
        var scenarios = new (string Name, string Inject)[]
        {
            ("no faults", ""),
            ("bit errors 1e-5", "ber=1e-5"),
            ("module resets", "reset=right.shoulder@5s,reset=left.forearm@12s"),
            ("bit errors 1e-4 + resets", "ber=1e-4,reset=right.shoulder@5s,reset=left.upper_arm@9s,reset=left.forearm@12s"),
        };
        var tracking = scenarios.Select(s => (s.Name, s.Inject, Report: HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = duration, Inject = FaultInjection.Parse(s.Inject), ContinueOnFault = true }, catalog))).ToList();

        var md = new StringBuilder();
        md.AppendLine("# Control loop: tick cost, allocations, latency, tracking");
        md.AppendLine();
        md.AppendLine(c, $"Command: `dotnet run -c Release --project bench/RobotControl.Bench -- loop --graph {graph} --duration {duration.TotalSeconds:0.###}s --out {outPath}`");
        md.AppendLine();
        md.AppendLine(c, $"Measured {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC on {Environment.ProcessorCount} cores shared with other work ({Environment.OSVersion}, .NET {Environment.Version}). The graph: two simulated Touch devices replaying the demonstration trajectory (up to ~70 mm/s at the tool, two clutch presses per arm) through homing (left mirrored), scaling 0.5, clutch, IK, walls and damping into the virtual LB/CRB robot running the module firmware; virtual clock, 1 kHz loop, bus cycles back to back.");
        md.AppendLine();
        md.AppendLine("## Tick cost (Stopwatch around the graph's tick: every plug-in and the robot node's port exchange)");
        md.AppendLine();
        md.AppendLine("| run | ticks | median us | p99 us | max us | deadline misses |");
        md.AppendLine("|---|---|---|---|---|---|");
        md.AppendLine(c, $"| cold (first in process, includes JIT) | {cold.Ticks} | {cold.TickMedianUs:F1} | {cold.TickP99Us:F1} | {cold.TickMaxUs:F1} | {cold.DeadlineMisses} |");
        md.AppendLine(c, $"| warm (second in process) | {warm.Ticks} | {warm.TickMedianUs:F1} | {warm.TickP99Us:F1} | {warm.TickMaxUs:F1} | {warm.DeadlineMisses} |");
        md.AppendLine();
        md.AppendLine(c, $"Aim: p99 < 100 us. Warm p99 / aim = {warm.TickP99Us / 100:F2}.");
        md.AppendLine();
        md.AppendLine("## Allocations per tick");
        md.AppendLine();
        md.AppendLine(c, $"{allocated} bytes over {measuredTicks} ticks (after the first second) = {(measuredTicks == 0 ? 0 : allocated / (double)measuredTicks):F3} bytes/tick (GC.GetAllocatedBytesForCurrentThread around each tick, warm run).");
        md.AppendLine();
        md.AppendLine("## Latency: Touch sample -> setpoint frame on the virtual wire");
        md.AppendLine();
        md.AppendLine("From the tick that samples the Touch (virtual time) to the end of the first sync-write frame after it (the frame carrying that tick's setpoints), on the virtual clock. The bus cycles back to back, so the wait is for the cycle in progress to finish.");
        md.AppendLine();
        md.AppendLine("| samples | median ms | p99 ms | max ms | bus cycle (mean) ms |");
        md.AppendLine("|---|---|---|---|---|");
        md.AppendLine(c, $"| {latencies.Count} | {Percentile(latencies, 0.5):F3} | {Percentile(latencies, 0.99):F3} | {latencies.Max():F3} | {latencies.CycleMs:F3} |");
        md.AppendLine();
        md.AppendLine("## Tracking error (|commanded tool position - FK(reported joints)|, both arms, every tick)");
        md.AppendLine();
        md.AppendLine("| faults | rms mm | max mm | deadline misses | CRC errors | timeouts | retries | faults reported |");
        md.AppendLine("|---|---|---|---|---|---|---|---|");
        foreach (var (name, inject, r) in tracking)
        {
            md.AppendLine(c, $"| {name} (`{(inject.Length == 0 ? "-" : inject)}`) | {r.TrackingRmsMm:F3} | {r.TrackingMaxMm:F3} | {r.DeadlineMisses} | {r.Bus.CrcErrors} | {r.Bus.Timeouts} | {r.Bus.Retries} | {r.Faults.Count} |");
        }

        md.AppendLine();
        md.AppendLine(c, $"Aim: RMS < 2 mm at surgical speeds; with faults RMS / without = {tracking[^1].Report.TrackingRmsMm / Math.Max(1e-9, tracking[0].Report.TrackingRmsMm):F2}.");
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(outPath))!);
        File.WriteAllText(outPath, md.ToString());
        Console.WriteLine(md.ToString());
        return 0;
    }

    private sealed class LatencyList : List<double>
    {
        public double CycleMs { get; init; }
    }

    private static LatencyList Latencies(List<long> tickTimes, FrameTapLink tap, long frequency, RunReport report)
    {
        _ = report;
        var writes = tap.SyncWrites;
        var byteTicks = 10.0 * frequency / tap.BaudRate;
        var cycle = writes.Count > 1 ? (writes[^1].Timestamp - writes[writes.Count / 2].Timestamp) / (double)(writes.Count - 1 - (writes.Count / 2)) / frequency * 1000 : 0;
        var result = new LatencyList { CycleMs = cycle };
        var w = 0;
        foreach (var t in tickTimes)
        {
            while (w < writes.Count && writes[w].Timestamp < t)
            {
                w++;
            }

            if (w == writes.Count)
            {
                break;
            }

            var end = writes[w].Timestamp + (writes[w].Bytes * byteTicks);
            result.Add((end - t) * 1000.0 / frequency);
        }

        return result;
    }

    private static double Percentile(List<double> values, double p)
    {
        var sorted = values.Order().ToList();
        return sorted.Count == 0 ? 0 : sorted[Math.Min(sorted.Count - 1, (int)Math.Ceiling(p * sorted.Count) - 1)];
    }
}
