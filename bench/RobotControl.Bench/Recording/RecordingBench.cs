using System.Diagnostics;
using System.Globalization;
using System.Text;
using RobotControl.Cli;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.Host.Session;
using RobotControl.Runtime.GraphFiles;

namespace RobotControl.Bench.Recording;

/// <summary>
/// <c>recording [--graph graphs/teleop-lb.json] [--duration 20s] [--out docs/perf/recording.md]</c>: what recording a
/// session (MCAP, <c>--record</c>) costs. (1) The loop's tick (Stopwatch around the whole step, the tick observers
/// and so the recorder's tap included) and its allocations, without and with recording, side by side in lockstep on
/// two threads of one process, on the main job. (2) File size per minute of loop time at decimation 1 and 10. (3) The writer's throughput: rows
/// of the main job's layout encoded and written (JSON, chunks, CRCs) on one thread, messages per second.
/// </summary>
internal sealed class RecordingBench : IBenchCommand
{
    /// <summary>Rounds, each a pair of runs side by side: without and with recording.</summary>
    private const int Rounds = 5;

    public string Name => "recording";

    public string Description => "Session recording (MCAP): tick p99 with vs without, allocations, file size per minute, writer msgs/s.";

    public int Run(string[] args)
    {
        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var duration = RunDuration.Parse(BenchArgs.Value(args, "--duration") ?? "20s");
        var outPath = BenchArgs.Value(args, "--out") ?? "docs/perf/recording.md";
        var catalog = ShippedPlugins.Catalog();
        var c = CultureInfo.InvariantCulture;
        var dir = Directory.CreateTempSubdirectory("rc-bench-rec-").FullName;
        HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = TimeSpan.FromSeconds(2) }, catalog); // JIT warm-up

        var rows = new List<(string Name, TickSample Ticks, RecordingSummary? Recording)>();
        for (var round = 0; round < Rounds; round++)
        {
            var pair = SideBySide(graph, duration, catalog, new RecordingOptions { Path = Path.Combine(dir, $"with-{round}.mcap") });
            rows.Add(("without recording", pair.Without, null));
            rows.Add(("with recording (decimate 1)", pair.With, pair.With.Recording));
        }

        var decimated = HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = duration, Record = new RecordingOptions { Path = Path.Combine(dir, "decimate-10.mcap"), Decimate = 10 } }, catalog).Recording!;
        var plain = HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = duration, Record = new RecordingOptions { Path = Path.Combine(dir, "plain.mcap"), Compression = McapCompression.None } }, catalog).Recording!;
        var throughput = new[] { McapCompression.Zstd, McapCompression.None }.Select(z => (Compression: z, Result: WriterThroughput(graph, catalog, Path.Combine(dir, "throughput.mcap"), z))).ToList();
        Directory.Delete(dir, recursive: true);

        var minutes = duration.TotalMinutes;
        var ratios = rows.Chunk(2).Select(pair => pair[1].Ticks.P99Us / pair[0].Ticks.P99Us).Order().ToList();
        static double Median(IEnumerable<double> values) => values.Order().ElementAt(Rounds / 2);
        var without = Median(rows.Where(r => r.Recording is null).Select(r => r.Ticks.P99Us));
        var withRec = Median(rows.Where(r => r.Recording is not null).Select(r => r.Ticks.P99Us));
        var md = new StringBuilder();
        md.AppendLine("# Session recording (MCAP): loop cost, file size, writer throughput");
        md.AppendLine();
        md.AppendLine(c, $"Command: `dotnet run -c Release --project bench/RobotControl.Bench -- recording --graph {graph} --duration {duration.TotalSeconds:0.###}s --out {outPath}`");
        md.AppendLine();
        md.AppendLine(c, $"Measured {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC on {Environment.ProcessorCount} cores shared with other work ({Environment.OSVersion}, .NET {Environment.Version}). The main job (two-arm teleoperation on the virtual robot, firmware in the loop, virtual clock, 1 kHz). Each round runs the two side by side, on two threads in lockstep (each tick waits for the other run's same tick), after a warm-up run; ticks take no loop time (`VirtualTickCost.Free`), so the two runs stay the same run.");
        md.AppendLine();
        md.AppendLine("## Loop tick: the whole step (graph, robot node and the tick observers, so the recorder's tap), thread CPU time");
        md.AppendLine();
        md.AppendLine("CPU time of the loop's thread (`ThreadCpuClock`) is what the loop itself spends; the wall-clock p99 is shown too, but on a virtual run the loop runs several times faster than real time and, on 2 shared cores, the writer thread (working at that multiple of its real-time rate) and other people's work preempt it.");
        md.AppendLine();
        md.AppendLine("| run | ticks | CPU median us | CPU p99 us | CPU max us | wall p99 us | bytes allocated per tick | loop rows dropped |");
        md.AppendLine("|---|---|---|---|---|---|---|---|");
        foreach (var (name, t, rec) in rows)
        {
            md.AppendLine(c, $"| {name} | {t.Ticks} | {t.MedianUs:F1} | {t.P99Us:F1} | {t.MaxUs:F1} | {t.WallP99Us:F1} | {t.BytesPerTick:F2} | {rec?.DroppedRows.ToString(c) ?? "-"} |");
        }

        md.AppendLine();
        md.AppendLine(c, $"CPU p99 with / without recording, each round's pair side by side: {string.Join(", ", ratios.Select(r => r.ToString("F3", c)))}; median **{ratios[Rounds / 2]:F3}** (aim: within 1.10). Medians of the p99s: {withRec:F1} / {without:F1} us.");
        md.AppendLine();
        md.AppendLine("## File size per minute of loop time");
        md.AppendLine();
        md.AppendLine("| chunks | decimation (graph signals, devices, tool poses) | messages | MB | MB per minute |");
        md.AppendLine("|---|---|---|---|---|");
        var full = rows.Last(r => r.Recording is not null).Recording!;
        md.AppendLine(c, $"| zstd (the default) | 1 (loop rate) | {full.Messages} | {full.Bytes / 1e6:F1} | {full.Bytes / 1e6 / minutes:F0} |");
        md.AppendLine(c, $"| zstd | 10 | {decimated.Messages} | {decimated.Bytes / 1e6:F1} | {decimated.Bytes / 1e6 / minutes:F0} |");
        md.AppendLine(c, $"| uncompressed | 1 (loop rate) | {plain.Messages} | {plain.Bytes / 1e6:F1} | {plain.Bytes / 1e6 / minutes:F0} |");
        md.AppendLine();
        md.AppendLine("## Writer throughput (one thread: JSON encoding, chunks, compression, CRC-32, file writes)");
        md.AppendLine();
        md.AppendLine("20,000 rows of the main job's layout, every value changing every row, the link frames every tenth row (as at 1 kHz).");
        md.AppendLine();
        md.AppendLine("| chunks | messages | s | messages/s | loop rows/s (six messages a row) |");
        md.AppendLine("|---|---|---|---|---|");
        foreach (var (compression, (messages, seconds)) in throughput)
        {
            md.AppendLine(c, $"| {(compression.Length == 0 ? "uncompressed" : compression)} | {messages} | {seconds:F2} | **{messages / seconds:F0}** | {messages / seconds / 6:F0} |");
        }
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(outPath))!);
        File.WriteAllText(outPath, md.ToString());
        Console.Write(md);
        return 0;
    }

    /// <summary>
    /// The main job twice at once, on two threads in lockstep (each tick waits for the other run's same tick): without
    /// recording, and with it. Both see the same moments of the machine (its other work, its host's stalls), so their
    /// ratio is the recording's cost rather than the time of day. Ticks take no loop time (the runs stay identical).
    /// </summary>
    private static (TickSample Without, TickSample With) SideBySide(string graph, TimeSpan duration, Runtime.Discovery.PluginCatalog catalog, RecordingOptions record)
    {
        using var lockstep = new Barrier(2);
        TickSample Run(RecordingOptions? r)
        {
            try
            {
                return Measure(graph, duration, catalog, r, lockstep);
            }
            finally
            {
                lockstep.RemoveParticipant(); // a run that ends first lets the other go on alone
            }
        }

        var without = Task.Factory.StartNew(() => Run(null), TaskCreationOptions.LongRunning);
        var with = Task.Factory.StartNew(() => Run(record), TaskCreationOptions.LongRunning);
        return (without.GetAwaiter().GetResult(), with.GetAwaiter().GetResult());
    }

    private static TickSample Measure(string graph, TimeSpan duration, Runtime.Discovery.PluginCatalog catalog, RecordingOptions? record, Barrier lockstep)
    {
        var ticks = new List<double>((int)(duration.TotalSeconds * 1000) + 16);
        var cpu = new List<double>(ticks.Capacity);
        long allocated = 0;
        var report = HeadlessRun.RunVirtual(new RunOptions { GraphPath = graph, Duration = duration, Record = record, TickCost = VirtualTickCost.Free }, catalog, new VirtualRunHooks
        {
            AroundTick = (loop, _) =>
            {
                lockstep.SignalAndWait();
                var bytes = GC.GetAllocatedBytesForCurrentThread();
                var cpuStart = ThreadCpuClock.NowNs();
                var start = Stopwatch.GetTimestamp();
                loop.Step();
                var us = Stopwatch.GetElapsedTime(start).TotalMicroseconds;
                var cpuUs = (ThreadCpuClock.NowNs() - cpuStart) * 1e-3;
                if (loop.TickCount > 1000)
                {
                    allocated += GC.GetAllocatedBytesForCurrentThread() - bytes;
                    ticks.Add(us);
                    cpu.Add(cpuUs);
                }
            },
        });
        ticks.Sort();
        cpu.Sort();
        static double At(List<double> sorted, double p) => sorted[Math.Min(sorted.Count - 1, (int)(p * sorted.Count))];
        return new TickSample(report.Ticks, At(cpu, 0.5), At(cpu, 0.99), cpu[^1], At(ticks, 0.99), allocated / (double)ticks.Count) { Recording = report.Recording };
    }

    /// <summary>Rows of the main job's layout (values from its initial state) encoded and written on this thread only.</summary>
    private static (ulong Messages, double Seconds) WriterThroughput(string graph, Runtime.Discovery.PluginCatalog catalog, string file, string compression)
    {
        var loaded = GraphFile.Load(graph, catalog, TimeProvider.System);
        var layout = new RecordingLayout(loaded);
        var row = new double[layout.Width];
        using var writer = new McapWriter(File.Create(file), string.Empty, SessionRecorder.Library, compression: compression);
        using var channels = new RecordingChannels(writer, layout, []);
        var watch = Stopwatch.StartNew();
        for (var tick = 0UL; tick < 20_000; tick++)
        {
            for (var i = 0; i < row.Length; i++)
            {
                row[i] = Math.Sin((tick * 0.001) + i); // a value that moves, as the robot's do: what compression meets
            }

            channels.WriteRow(row, tick * 1_000_000UL, full: true, links: tick % 10 == 0);
        }

        writer.Finish();
        var seconds = watch.Elapsed.TotalSeconds;
        return (writer.MessageCounts.Values.Aggregate(0UL, (a, b) => a + b), seconds);
    }


    private sealed record TickSample(long Ticks, double MedianUs, double P99Us, double MaxUs, double WallP99Us, double BytesPerTick)
    {
        public RecordingSummary? Recording { get; init; }
    }
}
