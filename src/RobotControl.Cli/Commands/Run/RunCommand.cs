using RobotControl.Definitions.Model;
using System.CommandLine;
using System.Globalization;
using RobotControl.Cli.Commands.Recording;
using RobotControl.Cli.Options;
using RobotControl.Cli.Output;
using RobotControl.Definitions.Loading;
using RobotControl.Host.Harness;
using RobotControl.Host.Session;
using RobotControl.Plugins.Link.Stations;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using Spectre.Console;

namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// <c>robotctl run &lt;graph&gt; [--virtual] [--duration 20s] [--report report.json] [--inject ber=1e-5,reset=right.shoulder@5s]
/// [--plugins dir] [--seed n] [--set instance.setting=value ...]</c>: the headless harness. Loads the graph, runs it against the virtual robot (running
/// the firmware, on a virtual clock) or the graph's transport, shows progress, prints a summary and writes the report.
/// </summary>
internal sealed class RunCommand : ICliCommand
{
    /// <summary>Longest run accepted (a day of loop time).</summary>
    internal static readonly TimeSpan MaxDuration = TimeSpan.FromDays(1);

    /// <inheritdoc />
    public Command Build()
    {
        var graph = new Argument<FileInfo>("graph") { Description = "Graph file, e.g. graphs/teleop-lb.json" };
        var isVirtual = new Option<bool>("--virtual") { Description = "Run against the virtual robot (real firmware, simulated motors) on a virtual clock, deterministically and as fast as possible" };
        var duration = CliOption.Duration("--duration", "Loop time to run, e.g. 20s, 500ms, 2m", TimeSpan.FromMilliseconds(1), MaxDuration, TimeSpan.FromSeconds(20));
        var report = CliOption.OutputFile("--report", "Write the report (JSON) to this file (checked before the run starts)");
        var inject = new Option<string?>("--inject") { Description = $"Faults for the virtual robot, comma-separated: {FaultInjection.Syntax} (see docs/safety.md)" };
        var plugins = new Option<DirectoryInfo?>("--plugins") { Description = "Also load plug-in assemblies from this folder (one load context each)" };
        var seed = CliOption.Number("--seed", "Seed of the virtual robot's noise and wire faults", 0, int.MaxValue, 1);
        var set = new Option<string[]>("--set") { Description = "Override a setting of a graph instance for this run, e.g. sim.endpoint=tcp://127.0.0.1:23456 (repeatable)", Arity = ArgumentArity.ZeroOrMore };
        var transport = new Option<string?>("--transport") { Description = "Open this transport instead of the graph's, e.g. serial:/dev/pts/3?baud=1000000 (virtual[:...] is --virtual)" };
        var rtPriority = CliOption.Number("--rt-priority", "Real time: run the bus and loop threads with SCHED_FIFO at this priority (1..99; 0: normal scheduling)", 0, 99, 0);
        var cpu = CliOption.OptionalNumber<int>("--cpu", "Real time: pin the bus and loop threads to this CPU", 0, 1023);
        var record = RecordOptions.Create();
        var tickCost = new Option<string>("--tick-cost") { Description = "With --virtual: measured (default: a tick's CPU time counts against its period, so a graph too slow for its rate misses) or free (ticks take no loop time: the run is exactly reproducible on any machine)", DefaultValueFactory = _ => "measured" };
        tickCost.AcceptOnlyFromAmong("measured", "free");
        var link = new Option<string?>("--link") { Description = "Two stations (docs/link.md): the NATS server the surgeon's station sends its E-STOP through to the robot station, e.g. nats://127.0.0.1:4222 (with --station)" };
        var station = new Option<string?>("--station") { Description = "With --link: the robot station's name on the server (its commands travel on rc.<station>.command), e.g. lb1" };
        var linkPlaintext = new Option<bool>("--link-plaintext-remote") { Description = "With --link: allow a plain-text nats:// server off the loopback interface (commands and credentials cross the network unencrypted)" };
        var continueOnFault = new Option<bool>("--continue-on-fault") { Description = "Keep commanding when the robot faults (default: stop, motors off, exit 1)" };
        var command = new Command("run", "Headless run of a plug-in graph: live progress, summary, report.json.");
        command.Arguments.Add(graph);
        command.Options.Add(isVirtual);
        command.Options.Add(duration);
        command.Options.Add(report);
        command.Options.Add(inject);
        command.Options.Add(plugins);
        command.Options.Add(seed);
        command.Options.Add(set);
        command.Options.Add(transport);
        command.Options.Add(continueOnFault);
        command.Options.Add(tickCost);
        command.Options.Add(rtPriority);
        command.Options.Add(cpu);
        command.Options.Add(link);
        command.Options.Add(station);
        command.Options.Add(linkPlaintext);
        record.AddTo(command);
        command.SetAction(parse => Run(
            parse.GetValue(graph)!.FullName,
            parse.GetValue(isVirtual),
            parse.GetValue(duration),
            parse.GetValue(report)?.FullName,
            parse.GetValue(inject),
            parse.GetValue(plugins)?.FullName,
            parse.GetValue(seed),
            parse.GetValue(set) ?? [],
            new RunExtras(parse.GetValue(transport), parse.GetValue(continueOnFault), parse.GetValue(rtPriority), parse.GetValue(cpu)) { Record = record.Value(parse), TickCost = parse.GetValue(tickCost) == "free" ? VirtualTickCost.Free : VirtualTickCost.Measured, Link = parse.GetValue(link), Station = parse.GetValue(station), LinkPlaintextRemote = parse.GetValue(linkPlaintext) },
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Runs the command; returns the exit code (0 ok, 1 faults or deadline misses, 2 bad input).</summary>
    internal static int Run(string graphPath, bool isVirtual, TimeSpan duration, string? reportPath, string? injectText, string? pluginsFolder, int seed, IReadOnlyList<string> settingOverrides, RunExtras extras, TextWriter output, TextWriter error)
    {
        var catalog = ShippedPlugins.Catalog(pluginsFolder);
        foreach (var problem in catalog.Problems)
        {
            error.WriteLine($"plug-ins: {problem}");
        }

        RunOptions options;
        bool hasRobot;
        StationAddress? linkAddress;
        try
        {
            isVirtual = extras.ResolveVirtual(isVirtual);
            options = new RunOptions
            {
                GraphPath = graphPath,
                Virtual = isVirtual,
                Duration = duration,
                Inject = FaultInjection.Parse(injectText),
                Seed = seed,
                SettingOverrides = [.. settingOverrides.Select(SettingOverride.Parse)],
                Transport = isVirtual ? null : extras.Transport,
                ContinueOnFault = extras.ContinueOnFault,
                Threads = extras.Threads(),
                Record = extras.Record?.Options(error),
                TickCost = extras.TickCostFor(isVirtual),
            };
            hasRobot = RunPreflight.Check(options, catalog);
            linkAddress = extras.LinkAddress();
        }
        catch (Exception ex) when (ex is FormatException or GraphException or RobotDataException)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        if (!hasRobot)
        {
            return StationCommand.Run(options, catalog, linkAddress, reportPath, output, error);
        }

        using var linkStop = new CancellationTokenSource();
        var responder = linkAddress is null ? null : RobotStationEndpoint.Start(linkAddress, _ =>
        {
            linkStop.Cancel();
            return "E-STOP taken: the supervisor trips operator (E_STOP) at the robot station's next bus cycle";
        });
        try
        {
            if (responder is not null)
            {
                output.WriteLine($"link: robot station '{responder.Address.Station}' takes the surgeon's E-STOP on {responder.Address.CommandSubject} at {responder.Address.Url}");
            }

            return RunRobot(options with { LinkEmergencyStop = linkStop.Token }, catalog, reportPath, output, error, p => responder?.Publish(new StationStatus(p.RunLevel, p.Trips, p.LastTrip)));
        }
        finally
        {
            responder?.DisposeAsync().AsTask().Wait();
        }
    }

    private static int RunRobot(RunOptions options, PluginCatalog catalog, string? reportPath, TextWriter output, TextWriter error, Action<RunProgress> onProgress)
    {
        var graphPath = options.GraphPath;
        var isVirtual = options.Virtual;
        var c = CultureInfo.InvariantCulture;
        output.WriteLine(string.Create(c, $"run {Path.GetFileName(graphPath)}: {(!isVirtual ? "real time" : options.TickCost == VirtualTickCost.Free ? "virtual robot (firmware in the loop), virtual clock, ticks take no loop time" : "virtual robot (firmware in the loop), virtual clock")}, {options.Duration.TotalSeconds:0.###} s, faults: {options.Inject}"));
        RunReport result;
        using var signals = new StopSignals(error);
        using var keys = ReferenceEquals(output, Console.Out) ? OperatorKeys.FromConsole(error) : null; // not when run in-process (tests)
        options = options with { Stop = signals.Token, EmergencyStop = keys?.EmergencyStop ?? default };
        if (keys is not null)
        {
            output.WriteLine(OperatorKeys.Help);
        }

        try
        {
            var interactive = ReferenceEquals(output, Console.Out) && !Console.IsOutputRedirected && AnsiConsole.Profile.Capabilities.Interactive;
            result = interactive ? RunWithProgressBar(options, catalog, onProgress) : RunWithLines(options, catalog, output, onProgress);
        }
        catch (GraphException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }
        catch (Exception ex) when (ex is InvalidOperationException or FormatException or IOException)
        {
            error.WriteLine($"run failed: {ex.Message}");
            return 2;
        }

        if (NonFinite(result) is { } field)
        {
            error.WriteLine($"run: the {field} is not a finite number: the robot file's geometry or the graph's settings are out of range; no report written");
            return 1;
        }

        Summarise(result, output);
        if (result.Recording is { Stopped: null } recording)
        {
            output.WriteLine(recording.ToString());
        }

        RunEnd.Tell(result, output, error);
        if (reportPath is not null)
        {
            AtomicFile.WriteAllText(reportPath, result.ToJson());
            output.WriteLine($"report: {reportPath}");
        }

        return RunEnd.ExitCode(result);
    }

    /// <summary>The first measure of <paramref name="r"/> that is not finite (a report holds numbers only), or null.</summary>
    internal static string? NonFinite(RunReport r) =>
        new (string Name, double Value)[]
        {
            ("loop time", r.DurationSeconds), ("median tick time", r.TickMedianUs), ("p99 tick time", r.TickP99Us), ("longest tick time", r.TickMaxUs),
            ("tracking rms", r.TrackingRmsMm), ("largest tracking error", r.TrackingMaxMm),
        }.FirstOrDefault(m => !double.IsFinite(m.Value)).Name;

    private static RunReport RunWithLines(RunOptions options, PluginCatalog catalog, TextWriter output, Action<RunProgress> onProgress)
    {
        var c = CultureInfo.InvariantCulture;
        var lastSecond = -1;
        return HeadlessRun.Run(options with { ProgressInterval = TimeSpan.FromMilliseconds(100) }, catalog, p =>
        {
            onProgress(p);
            var second = (int)p.Elapsed.TotalSeconds;
            if (second != lastSecond && (second % 2 == 0 || p.Elapsed >= p.Duration))
            {
                lastSecond = second;
                output.WriteLine(string.Create(c, $"  t={p.Elapsed.TotalSeconds,6:F1} s  ticks {p.Ticks,7}  misses {p.DeadlineMisses}  tracking rms {p.TrackingRmsMm:F3} mm (now {p.TrackingNowMm:F3})  faults {p.Faults}  robot {p.RobotFaults}"));
            }
        });
    }

    private static RunReport RunWithProgressBar(RunOptions options, PluginCatalog catalog, Action<RunProgress> onProgress)
    {
        RunReport? result = null;
        AnsiConsole.Progress()
            .Columns(new TaskDescriptionColumn(), new ProgressBarColumn(), new PercentageColumn(), new ElapsedTimeColumn())
            .Start(ctx =>
            {
                var task = ctx.AddTask("running", maxValue: options.Duration.TotalSeconds);
                result = HeadlessRun.Run(options with { ProgressInterval = TimeSpan.FromMilliseconds(100) }, catalog, p =>
                {
                    onProgress(p);
                    task.Value = p.Elapsed.TotalSeconds;
                    task.Description = string.Create(CultureInfo.InvariantCulture, $"t={p.Elapsed.TotalSeconds:F1}s rms {p.TrackingRmsMm:F2} mm now {p.TrackingNowMm:F2} mm misses {p.DeadlineMisses} faults {p.Faults}");
                });
                task.Value = task.MaxValue;
            });
        return result!;
    }

    /// <summary>The silences the supervisor timed (host stalls, a loop behind, silent modules), which the deadline misses do not count: their number and the longest.</summary>
    private static string Silences(RunReport r)
    {
        var silences = (r.Safety?.Trips ?? []).Where(t => t.Check.IsSilence()).ToList();
        return silences.Count == 0
            ? string.Empty
            : string.Create(CultureInfo.InvariantCulture, $"; {silences.Count} silence trip(s), longest {silences.Max(t => t.Measured):0.#} ms ({silences.MaxBy(t => t.Measured)!.Check.Name()})");
    }

    private static void Summarise(RunReport r, TextWriter output)
    {
        var c = CultureInfo.InvariantCulture;
        output.WriteLine(string.Create(c, $"summary: {r.Ticks} ticks in {r.DurationSeconds:F3} s of loop time, {r.DeadlineMisses} deadline misses (ticks started late){Silences(r)}"));
        output.WriteLine(string.Create(c, $"  tick time (us): median {r.TickMedianUs:F1}, p99 {r.TickP99Us:F1}, max {r.TickMaxUs:F1}"));
        output.WriteLine(string.Create(c, $"  tracking error (mm): rms {r.TrackingRmsMm:F3}, max {r.TrackingMaxMm:F3}"));
        output.WriteLine(string.Create(c, $"  bus: {r.Bus.Frames} frames, {r.Bus.CrcErrors} CRC errors, {r.Bus.Timeouts} timeouts, {r.Bus.Retries} retries, {r.Bus.LateReplies} late replies"));
        foreach (var line in r.Safety?.Lines() ?? [])
        {
            output.WriteLine(line);
        }

        output.WriteLine(string.Create(c, $"  faults: {r.Faults.Count}"));
        foreach (var f in r.Faults.Take(20))
        {
            output.WriteLine(string.Create(c, $"    {f.TimeSeconds,8:F3} s  {f.Source}: {f.Message}"));
        }

        if (r.Faults.Count > 20)
        {
            output.WriteLine($"    ... {r.Faults.Count - 20} more in the report");
        }
    }
}
