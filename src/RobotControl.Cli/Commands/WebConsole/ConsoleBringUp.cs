using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Commands.Bus;
using RobotControl.Cli.Commands.Commission;
using RobotControl.Cli.Commands.Run;
using RobotControl.Definitions.Loading;
using RobotControl.Host.Session;
using RobotControl.Robot.Commissioning;
using RobotControl.WebConsole.BringUp;
using RobotControl.WebConsole.Server;

namespace RobotControl.Cli.Commands.WebConsole;

/// <summary>
/// <c>robotctl console --bring-up &lt;robot-file&gt; --transport serial:&lt;port&gt; --unit &lt;name&gt; [--units dir]</c>:
/// the console's Bring-up page (<see cref="BringUpSession"/>) over a box of boards, no robot session, until Ctrl+C or
/// SIGTERM, which stop a running step first (a calibration: its motors off, read back). Bad input is one line and exit 2.
/// </summary>
internal static class ConsoleBringUp
{
    /// <summary>The options of the bring-up mode.</summary>
    /// <param name="RobotFile">The robot file.</param>
    /// <param name="Transport">The <c>--transport</c>, or null.</param>
    /// <param name="Unit">The <c>--unit</c>, or null.</param>
    /// <param name="Units">The <c>--units</c> directory, or null.</param>
    /// <param name="MarginMs">The reply margin, ms.</param>
    internal sealed record Options(FileInfo RobotFile, string? Transport, string? Unit, DirectoryInfo? Units, double MarginMs);

    /// <summary>Serves the bring-up page; returns the exit code.</summary>
    public static int Run(Options given, bool noGraph, ConsoleAccess access, TextWriter output, TextWriter error)
    {
        BringUpSetup setup;
        ConsoleServerOptions serving;
        try
        {
            setup = Setup(given, noGraph);
            serving = access.Options();
        }
        catch (Exception ex) when (ex is ArgumentException or FormatException or IOException or RobotDataException or InvalidOperationException)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        using var session = new BringUpSession(setup);
        ConsoleServer server;
        try
        {
            server = ConsoleServer.StartAsync(session, serving).GetAwaiter().GetResult();
        }
        catch (Exception ex) when (ex is IOException or FormatException)
        {
            error.WriteLine($"console: cannot serve on {serving.Bind}: {ex.Message}");
            return 2;
        }

        output.WriteLine($"console: bring-up of unit {setup.Unit} ({setup.UnitPath}), {setup.Robot.Name} on {setup.Transport}");
        output.WriteLine($"console: {server.OpenUrl}#bringup");
        if (ConsoleAccess.Warning(serving) is { } warning)
        {
            error.WriteLine(warning);
        }

        output.WriteLine("console: Ctrl+C stops");
        using (var signals = new StopSignals(error, "a running step stops first (its motors off, read back), then the pages close"))
        {
            using var stepFirst = signals.Token.Register(() => session.StopMotorsNow("stop requested"));
            signals.Token.WaitHandle.WaitOne();
            _ = session.Close();
            output.WriteLine($"console: stopped; {session.Job?.Outcome ?? "no step was run"}");
            ConsoleCommand.CloseServer(server, error);
        }

        return 0;
    }

    private static BringUpSetup Setup(Options given, bool noGraph)
    {
        if (!noGraph)
        {
            throw new ArgumentException("console: give a graph file or --bring-up, not both");
        }

        if (given.Transport is null || given.Unit is null)
        {
            throw new ArgumentException("--bring-up: give --transport serial:<port> (the box of boards) and --unit <name>");
        }

        if (!given.RobotFile.Exists)
        {
            throw new ArgumentException($"--bring-up {given.RobotFile.FullName}: no such robot file");
        }

        var robot = RobotLoader.Load(given.RobotFile.FullName);
        var path = UnitFile.PathOf(given.Units?.FullName ?? CommissionCommand.DefaultUnitsDirectory, given.Unit);
        _ = UnitFile.Load(path); // a file that is not a unit file is refused now, not at the first step
        var line = new BusLine(given.Transport, given.RobotFile.FullName, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(given.MarginMs) });
        if (line.Uri.Kind == LinkKind.Virtual)
        {
            throw new ArgumentException("--transport virtual: a virtual robot starts commissioned; serve a box of boards with robotctl bus-sim --pty --factory and give its serial: path");
        }

        BusClient Open(int baud)
        {
            RobotConnection.CheckTransport(line.Transport(baud));
            return new BusClient(LinkFactory.Open(line.Transport(baud)), TimeProvider.System, line.Options);
        }

        using (Open(robot.Modules.BaudRate))
        {
            // the port opens: a wrong path is refused now
        }

        return new BringUpSetup(given.RobotFile.ToString(), robot, given.Unit, path, given.Transport, Open, TimeProvider.System);
    }
}
