using System.Globalization;
using RobotControl.Cli.Output;
using RobotControl.Host.Harness;
using RobotControl.Host.Station;
using RobotControl.Plugins.Link.Stations;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;

namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// <c>robotctl run</c> of a graph that names no robot: a station of a graph split at its wires (the surgeon's station
/// of docs/link.md), its loop on the wall clock until the duration ends or Ctrl+C / SIGTERM; a summary and the report.
/// </summary>
internal static class StationCommand
{
    /// <summary>What the station prints so the operator knows the E-STOP key.</summary>
    public const string Help = "E-STOP: type e and Enter (from a pipe: a line 'estop'): sent to the robot station until it answers; Ctrl+C ends this station's run";

    /// <summary>
    /// Runs <paramref name="options"/>' station; with <paramref name="link"/>, the command line's E-STOP goes to that
    /// robot station, repeated until answered. Returns the exit code (0 clean, 1 plug-in faults, misses or an E-STOP
    /// not answered, 2 bad input, 130 interrupted).
    /// </summary>
    public static int Run(RunOptions options, PluginCatalog catalog, StationAddress? link, string? reportPath, TextWriter output, TextWriter error)
    {
        var c = CultureInfo.InvariantCulture;
        StationReport report;
        using var signals = new StopSignals(error);
        var sender = link is null ? null : SurgeonStationEndpoint.Open(link);
        using var keys = ReferenceEquals(output, Console.Out) ? OperatorKeys.FromConsole(error) : null; // not when run in-process (tests)
        var unanswered = 0;
        Task? stopping = null;
        using var estop = keys?.EmergencyStop.Register(() => stopping = Task.Run(async () =>
        {
            if (sender is null)
            {
                error.WriteLine("E-STOP: this station drives no motor and has no --link to a robot station: use the robot's E-STOP");
                Interlocked.Increment(ref unanswered);
                return;
            }

            var outcome = await sender.SendAsync(StationCommands.EmergencyStop).ConfigureAwait(false);
            if (outcome.Answered)
            {
                error.WriteLine(string.Create(c, $"E-STOP acknowledged by robot station '{link!.Station}' {outcome.After.TotalMilliseconds:0} ms after the key ({outcome.Attempts} send(s)): {outcome.Line}"));
            }
            else
            {
                Interlocked.Increment(ref unanswered);
                error.WriteLine($"E-STOP NOT ACKNOWLEDGED: {outcome.Line}: use the robot's hardware E-STOP");
            }
        }));
        try
        {
            if (keys is not null)
            {
                output.WriteLine(Help);
            }

            sender?.Watch(output.WriteLine); // the robot station's run level and trips, and the link lost or back

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
        finally
        {
            stopping?.Wait(SurgeonStationEndpoint.GiveUpAfter + TimeSpan.FromSeconds(1)); // an E-STOP on its way is answered or given up on before the run ends
            sender?.DisposeAsync().AsTask().Wait();
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

        return unanswered > 0 && report.ExitCode == 0 ? 1 : report.ExitCode;
    }
}
