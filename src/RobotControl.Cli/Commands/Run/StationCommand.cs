using System.Globalization;
using RobotControl.Cli.Output;
using RobotControl.Host.Harness;
using RobotControl.Host.Station;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;

namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// <c>robotctl run</c> of a graph that names no robot: a station of a graph split at its wires (the surgeon's station
/// of docs/link.md), its loop on the wall clock until the duration ends or Ctrl+C / SIGTERM; a summary and the report.
/// </summary>
internal static class StationCommand
{
    /// <summary>Runs <paramref name="options"/>' station; returns the exit code (0 clean, 1 plug-in faults or misses, 2 bad input, 130 interrupted).</summary>
    public static int Run(RunOptions options, PluginCatalog catalog, string? reportPath, TextWriter output, TextWriter error)
    {
        var c = CultureInfo.InvariantCulture;
        StationReport report;
        using var signals = new StopSignals(error);
        try
        {
            var run = options with { Stop = signals.Token, ProgressInterval = TimeSpan.FromSeconds(1) };
            output.WriteLine(string.Create(c, $"run {Path.GetFileName(options.GraphPath)}: a station without a robot, wall clock, {options.Duration.TotalSeconds:0.###} s"));
            report = StationRun.Run(run, catalog, p =>
            {
                var second = (int)p.Elapsed.TotalSeconds;
                if (second % 2 == 0 || p.Elapsed >= p.Duration)
                {
                    output.WriteLine(string.Create(c, $"  t={p.Elapsed.TotalSeconds,6:F1} s  ticks {p.Ticks,7}  misses {p.DeadlineMisses}  plug-in faults {p.PluginFaults}"));
                }
            });
        }
        catch (Exception ex) when (ex is GraphException or InvalidOperationException or FormatException or IOException)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        foreach (var line in report.Lines())
        {
            output.WriteLine(line);
        }

        if (report.Interrupted)
        {
            error.WriteLine(string.Create(c, $"interrupted after {report.DurationSeconds:F3} s"));
        }

        if (reportPath is not null)
        {
            AtomicFile.WriteAllText(reportPath, report.ToJson());
            output.WriteLine($"report: {reportPath}");
        }

        return report.ExitCode;
    }
}
