using System.Diagnostics;
using System.Globalization;
using System.Text;
using RobotControl.Cli;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.WebConsole.Replay;

namespace RobotControl.Bench.Recording;

/// <summary>
/// <c>replay-open [--graph graphs/teleop-lb.json] [--minutes 10] [--file F.mcap] [--out docs/perf/replay-open.md]</c>:
/// what the replay console costs to open a long recording and seek to its middle. Records the main job for the given
/// loop time (virtual clock, every signal at the loop rate, zstd: the defaults of <c>--record</c>), or takes
/// <c>--file</c>; then, three times, opens it as <c>robotctl console --replay</c> does (<see cref="ReplaySession"/>)
/// and seeks to the middle until the plots' ring holds the row recorded there. Medians of the three, and each.
/// </summary>
internal sealed class ReplayOpenBench : IBenchCommand
{
    public string Name => "replay-open";

    public string Description => "Replay console: time to open a 10-minute recording and seek to its middle (median of 3), file size.";

    public int Run(string[] args)
    {
        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var minutes = double.Parse(BenchArgs.Value(args, "--minutes") ?? "10", CultureInfo.InvariantCulture);
        var outPath = BenchArgs.Value(args, "--out") ?? "docs/perf/replay-open.md";
        var c = CultureInfo.InvariantCulture;
        var dir = Directory.CreateTempSubdirectory("rc-bench-replay-").FullName;
        var file = BenchArgs.Value(args, "--file");
        var made = Stopwatch.StartNew();
        RecordingSummary? written = null;
        if (file is null)
        {
            file = Path.Combine(dir, "long.mcap");
            written = HeadlessRun.Run(new RunOptions { GraphPath = graph, Duration = TimeSpan.FromMinutes(minutes), Record = new RecordingOptions { Path = file } }, ShippedPlugins.Catalog()).Recording!;
        }

        var recordSeconds = made.Elapsed.TotalSeconds;
        var rounds = new List<(double OpenMs, double SeekMs, double Duration, double Row)>();
        for (var round = 0; round < 3; round++)
        {
            var watch = Stopwatch.StartNew();
            using var replay = new ReplaySession(file, TimeProvider.System);
            var open = watch.Elapsed.TotalMilliseconds;
            replay.Play(false);
            var middle = replay.DurationSeconds / 2;
            watch.Restart();
            replay.Seek(middle);
            replay.Pump();
            var seek = watch.Elapsed.TotalMilliseconds;
            var slice = replay.Signals.Read(0, [0], int.MaxValue);
            rounds.Add((open, seek, replay.DurationSeconds, slice.Times.Count == 0 ? double.NaN : slice.Times[^1]));
        }

        var bytes = new FileInfo(file).Length;
        Directory.Delete(dir, recursive: true);
        static double Median(IEnumerable<double> values) => values.Order().ElementAt(1);
        var md = new StringBuilder();
        md.AppendLine("# Replay console: opening a long recording and seeking to its middle");
        md.AppendLine();
        md.AppendLine(c, $"Command: `dotnet run -c Release --project bench/RobotControl.Bench -- replay-open --graph {graph} --minutes {minutes:0.###} --out {outPath}`");
        md.AppendLine();
        md.AppendLine(c, $"Measured {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC on {Environment.ProcessorCount} cores shared with other work ({Environment.OSVersion}, .NET {Environment.Version}). The recording: {(written is null ? Path.GetFileName(file) : $"the main job, {minutes:0.###} min of loop time on the virtual clock, every signal at the loop rate, zstd chunks ({written})")}, {bytes / 1e6:F1} MB{(written is null ? string.Empty : $", made in {recordSeconds:F0} s")}. The file was just written or read, so it is in the page cache: the figures are the reader's, not the disk's.");
        md.AppendLine();
        md.AppendLine("| round | open (index, timeline, model) ms | seek to the middle and fill the ring ms | recording s | row shown at s |");
        md.AppendLine("|---|---|---|---|---|");
        for (var i = 0; i < rounds.Count; i++)
        {
            var r = rounds[i];
            md.AppendLine(c, $"| {i + 1} | {r.OpenMs:F1} | {r.SeekMs:F1} | {r.Duration:F3} | {r.Row:F3} |");
        }

        md.AppendLine();
        md.AppendLine(c, $"Median of 3: open **{Median(rounds.Select(r => r.OpenMs)):F1} ms**, seek **{Median(rounds.Select(r => r.SeekMs)):F1} ms**, together **{Median(rounds.Select(r => r.OpenMs + r.SeekMs)):F1} ms**.");
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(outPath))!);
        File.WriteAllText(outPath, md.ToString());
        Console.Write(md);
        return 0;
    }

}
