using System.CommandLine;
using System.Diagnostics;
using System.Globalization;
using RobotControl.Cli.Commands.Recording;
using RobotControl.Cli.Commands.Run;
using RobotControl.Cli.Options;
using RobotControl.Cli.Output;
using RobotControl.Host.Harness;
using RobotControl.Host.Session;
using RobotControl.Runtime.Graph;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Editor;
using RobotControl.WebConsole.Server;
using RobotControl.WebConsole.Session;

namespace RobotControl.Cli.Commands.WebConsole;

/// <summary>
/// <c>robotctl console &lt;graph&gt; [--virtual | --transport &lt;uri&gt;] [--bind 127.0.0.1:5080] [--token T] [--allowed-host name]... [--https-cert file [--https-key file]] [--open [--page surgeon] [--kiosk]] [--inject silent=...] [--report session.json] [--rt-priority 80] [--cpu N]</c>:
/// starts the session and serves the web console (pages and JSON/WebSocket API) from this process until Ctrl+C or
/// SIGTERM. The stop switches the motors off, reads every module back, prints what they said and writes the session's
/// report (<c>--report</c>); the exit code is 0 when every module answered with torque off, 1 otherwise.
/// </summary>
internal sealed class ConsoleCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var graph = new Argument<FileInfo?>("graph") { Description = "Graph file, e.g. graphs/teleop-lb.json (none with --replay)", Arity = ArgumentArity.ZeroOrOne };
        var bringUp = new Option<FileInfo?>("--bring-up") { Description = "Serve the Bring-up page for this robot file instead of a robot: commission and calibrate a unit (with --transport serial:<port> --unit <name> [--units dir]; docs/bring-up.md)" };
        var unit = new Option<string?>("--unit") { Description = "With --bring-up: the unit's name, its record is <units>/<name>.json" };
        var units = new Option<DirectoryInfo?>("--units") { Description = $"With --bring-up: directory of unit files (default {Commission.CommissionCommand.DefaultUnitsDirectory})" };
        var margin = CliOption.Number("--margin-ms", "With --bring-up: reply timeout beyond the wire time, ms (USB adapters: their latency timer + 1)", 0.0, 1000.0, 3.0);
        var replay = new Option<FileInfo?>("--replay") { Description = "Serve the pages from a recording (robotctl run --record) instead of a robot: play, pause, 0.25x-4x, seek (docs/recording.md)" };
        var isVirtual = new Option<bool>("--virtual") { Description = "Run the virtual robot (real firmware, simulated motors) in real time" };
        var transport = new Option<string?>("--transport") { Description = "Bus transport instead of the graph's: serial:/dev/ttyUSB0?baud=1000000 | usb:0403:6001 | tcp:host:port" };
        var bind = new Option<string>("--bind") { Description = "Address and port to serve on (off this host: give --https-cert)", DefaultValueFactory = _ => "127.0.0.1:5080" };
        var token = new Option<string?>("--token") { Description = "The session's access token, 8 characters or more (default: a random one, printed in the URL)" };
        var allowedHosts = new Option<string[]>("--allowed-host") { Description = "A host name the console answers to besides localhost, the bind address and this machine's (repeatable)", AllowMultipleArgumentsPerToken = false };
        var httpsCert = new Option<FileInfo?>("--https-cert") { Description = "Serve HTTPS with this certificate: .pfx/.p12 (no password) or PEM (key in it or in --https-key)" };
        var httpsKey = new Option<FileInfo?>("--https-key") { Description = "The PEM private key of --https-cert" };
        var open = new Option<bool>("--open") { Description = "Open the console in a browser window (Chromium's --app mode) when one is installed" };
        var plugins = new Option<DirectoryInfo?>("--plugins") { Description = "Also load plug-in assemblies from this folder" };
        var seed = CliOption.Number("--seed", "Seed of the virtual robot's noise and wire faults", 0, int.MaxValue, 1);
        var inject = new Option<string?>("--inject") { Description = "Faults for the virtual robot: silent=<module>@<time>, e.g. silent=left.forearm@30s (see docs/safety.md)" };
        var page = new Option<string?>("--page") { Description = "The page --open shows: bus, plots, view3d, status, editor or surgeon" };
        var kiosk = new Option<bool>("--kiosk") { Description = "With --open: full screen, no browser controls (Chromium's --kiosk)" };
        var rtPriority = CliOption.Number("--rt-priority", "Real time, on a real bus: run the session's bus thread and the loop thread with SCHED_FIFO at this priority (1..99; 0: normal scheduling)", 0, 99, 0);
        var cpu = CliOption.OptionalNumber<int>("--cpu", "Real time, on a real bus: pin the bus and loop threads to this CPU", 0, 1023);
        var record = RecordOptions.Create();
        var report = CliOption.OutputFile("--report", "At the stop, write the session's report (JSON: last status, the stop's read-back, events, timings) to this file (checked before the session starts)");
        var command = new Command("console", "Web console: bus and controllers, plots, 3D view, run status, graph editor and the surgeon's view of a running session.");
        command.Arguments.Add(graph);
        foreach (var o in new Option[] { isVirtual, transport, bind, token, allowedHosts, httpsCert, httpsKey, open, plugins, seed, inject, page, kiosk, report, rtPriority, cpu })
        {
            command.Options.Add(o);
        }

        record.AddTo(command);
        foreach (var o in new Option[] { replay, bringUp, unit, units, margin })
        {
            command.Options.Add(o);
        }

        ConsoleAccess Access(ParseResult parse) => new ConsoleAccess(parse.GetValue(bind)!, parse.GetValue(token), parse.GetValue(allowedHosts) ?? [], parse.GetValue(httpsCert)?.FullName, parse.GetValue(httpsKey)?.FullName);
        command.SetAction(parse => parse.GetValue(replay) is { } file
            ? ConsoleReplay.Run(file.FullName, parse.GetValue(graph) is null, Access(parse), parse.InvocationConfiguration.Output, parse.InvocationConfiguration.Error)
            : parse.GetValue(bringUp) is { } robotFile
            ? ConsoleBringUp.Run(new ConsoleBringUp.Options(robotFile, parse.GetValue(transport), parse.GetValue(unit), parse.GetValue(units), parse.GetValue(margin)), parse.GetValue(graph) is null, Access(parse), parse.InvocationConfiguration.Output, parse.InvocationConfiguration.Error)
            : Run(
            parse.GetValue(graph)?.FullName,
            parse.GetValue(isVirtual),
            parse.GetValue(transport),
            Access(parse),
            parse.GetValue(open),
            parse.GetValue(plugins)?.FullName,
            parse.GetValue(seed),
            new ConsoleExtras(parse.GetValue(inject), parse.GetValue(page), parse.GetValue(kiosk), parse.GetValue(report)?.FullName, new RunExtras(null, false, parse.GetValue(rtPriority), parse.GetValue(cpu)) { Record = record.Value(parse) }),
            parse.InvocationConfiguration.Output,
            parse.InvocationConfiguration.Error));
        return command;
    }

    private static int Run(string? graphPath, bool isVirtual, string? transport, ConsoleAccess access, bool open, string? pluginsFolder, int seed, ConsoleExtras extras, TextWriter output, TextWriter error)
    {
        if (graphPath is null)
        {
            error.WriteLine("console: give a graph file, e.g. graphs/teleop-lb.json (or --replay file.mcap)");
            return 2;
        }

        if (isVirtual && transport is not null)
        {
            error.WriteLine("give --virtual or --transport, not both");
            return 2;
        }

        ConsoleServerOptions serving;
        try
        {
            serving = access.Options();
        }
        catch (FormatException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        LiveSession session;
        LiveSessionOptions options;
        try
        {
            if (transport is not null)
            {
                TransportOverride.Check(transport);
            }

            extras.CheckPage();
            options = new LiveSessionOptions { GraphPath = graphPath, Catalog = ShippedPlugins.Catalog(pluginsFolder), Virtual = isVirtual, Transport = transport, Seed = seed, Threads = extras.Scheduling.Threads() };
            // faults and the recording for the first session only, not for graphs started from the editor
            session = new LiveSession(options with { Inject = FaultInjection.Parse(extras.Inject), Record = extras.Scheduling.Record?.Options(error) });
        }
        catch (GraphException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }
        catch (Exception ex) when (ex is InvalidOperationException or FormatException or IOException or ArgumentException)
        {
            error.WriteLine($"console: {ex.Message}");
            return 2;
        }

        // The graph editor runs the graphs of the folder the given graph is in, on the same robot options.
        var switchable = new SwitchableSession(session);
        using var runner = new GraphRunner(switchable, graphPath, session.Transport, path => new LiveSession(options with { GraphPath = path }));
        var editor = new GraphEditor(new GraphFolder(Path.GetDirectoryName(graphPath)!), options.Catalog, runner);
        SessionEnd end;
        using (switchable)
        {
            ConsoleServer server;
            try
            {
                server = ConsoleServer.StartAsync(switchable, serving with { Editor = editor }).GetAwaiter().GetResult();
            }
            catch (Exception ex) when (ex is IOException or FormatException)
            {
                error.WriteLine($"console: cannot serve on {serving.Bind}: {ex.Message}");
                return 2;
            }

            var status = switchable.Status;
            output.WriteLine($"console: {status.Robot} on {status.Transport}, {status.ModulesFound} of {status.ModulesConfigured} modules found, loop {status.LoopRateHz:0} Hz");
            output.WriteLine($"console: {server.OpenUrl}");
            if (ConsoleAccess.Warning(serving) is { } warning)
            {
                error.WriteLine(warning);
            }

            if (open)
            {
                output.WriteLine(OpenBrowser(extras.Url(server.OpenUrl), extras.Kiosk));
            }

            output.WriteLine("console: Ctrl+C stops");
            using (var signals = new StopSignals(error, "motors off and read back first, then pages closed, loop off"))
            {
                using var motorsFirst = signals.Token.Register(() => switchable.StopMotorsNow("stop requested: motors off")); // from the signal's own thread
                signals.Token.WaitHandle.WaitOne();
                end = switchable.Close(); // the motors first (read back), whatever the pages and their requests are doing
                CloseServer(server, error);
            }
        }

        return Ended(end, extras.Report, output, error);
    }

    /// <summary>How long the pages' server may take to close its connections once the motors are off.</summary>
    internal static readonly TimeSpan ServerCloseWait = TimeSpan.FromSeconds(2);

    /// <summary>Closes the pages' server, waiting at most <see cref="ServerCloseWait"/> (a request that hangs does not hold the report).</summary>
    internal static void CloseServer(ConsoleServer server, TextWriter error)
    {
        if (!server.DisposeAsync().AsTask().Wait(ServerCloseWait))
        {
            error.WriteLine($"console: the pages' server did not close within {ServerCloseWait.TotalSeconds:0} s; the report is written without waiting for it");
        }
    }

    /// <summary>Says how the session ended and writes its report; 0 when every module answered with torque off.</summary>
    private static int Ended(SessionEnd end, string? reportPath, TextWriter output, TextWriter error)
    {
        output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"console: stopped after {end.Status.SessionSeconds:F1} s, {end.Status.Ticks} ticks, {end.Status.DeadlineMisses} deadline misses"));
        if (end.Stop is { } stop)
        {
            RunEnd.TellStop(stop, output, error);
        }

        if (reportPath is not null)
        {
            AtomicFile.WriteAllText(reportPath, end.ToJson());
            output.WriteLine($"report: {reportPath}");
        }

        return end.TorqueOff ? 0 : 1;
    }

    /// <summary>Starts a Chromium-family browser in app mode on <paramref name="url"/>; says what happened.</summary>
    private static string OpenBrowser(Uri url, bool kiosk)
    {
        foreach (var name in new[] { "chromium", "chromium-browser", "google-chrome", "microsoft-edge" })
        {
            var path = (Environment.GetEnvironmentVariable("PATH") ?? string.Empty).Split(':').Select(d => Path.Combine(d, name)).FirstOrDefault(File.Exists);
            if (path is null)
            {
                continue;
            }

            using var process = Process.Start(new ProcessStartInfo(path) { ArgumentList = { $"--app={url}", "--no-first-run", kiosk ? "--kiosk" : "--start-maximized" }, UseShellExecute = false });
            return $"console: opened {name} in {(kiosk ? "kiosk" : "app")} mode";
        }

        return "console: --open: no Chromium-family browser found (chromium, chromium-browser, google-chrome); open the URL above";
    }
}
