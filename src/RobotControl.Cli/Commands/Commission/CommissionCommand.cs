using System.CommandLine;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Commands.Bus;
using RobotControl.Cli.Options;
using RobotControl.Definitions.Loading;
using RobotControl.Host.Session;
using RobotControl.Modules;
using RobotControl.Robot.Commissioning;

namespace RobotControl.Cli.Commands.Commission;

/// <summary>
/// <c>robotctl commission &lt;robot-file&gt; --transport &lt;t&gt; --unit &lt;name&gt; [--yes]</c>: numbers and
/// parameterises a box of factory-fresh modules one at a time and records the unit (<see cref="Commissioner"/>,
/// <see cref="UnitFile"/>). Run again after any stop, it continues where it stopped.
/// </summary>
internal sealed class CommissionCommand : ICliCommand
{
    /// <summary>Where unit files live unless <c>--units</c> says otherwise.</summary>
    public const string DefaultUnitsDirectory = "hardware/units";

    /// <inheritdoc />
    public Command Build()
    {
        var robotFile = new Argument<FileInfo>("robot") { Description = "The robot data file the unit is built to, e.g. hardware/robots/lb-1.0.json" };
        var transport = new Option<string>("--transport") { Description = "The bus, e.g. serial:/dev/ttyUSB0 (opened at the factory baud)", Required = true };
        var unit = new Option<string>("--unit") { Description = "The unit's name: its record is <units>/<name>.json", Required = true };
        var units = new Option<DirectoryInfo>("--units") { Description = $"Directory of unit files (default {DefaultUnitsDirectory})" };
        var yes = new Option<bool>("--yes") { Description = "Non-interactive: wait for each module to answer instead of asking for Enter" };
        var margin = CliOption.Number("--margin-ms", "Reply timeout beyond the wire time, ms (USB adapters: their latency timer + 1)", 0.0, 1000.0, 3.0);
        var command = new Command("commission", "Number and parameterise factory-fresh modules one at a time, verify every value, record the unit; resumable.");
        command.Arguments.Add(robotFile);
        foreach (var o in new Option[] { transport, unit, units, yes, margin })
        {
            command.Options.Add(o);
        }

        command.SetAction(parse => BusOptions.Guard(parse, () =>
        {
            var file = parse.GetValue(robotFile)!;
            var directory = parse.GetValue(units)?.FullName ?? DefaultUnitsDirectory;
            var path = UnitFile.PathOf(directory, parse.GetValue(unit)!);
            if (!file.Exists)
            {
                throw new ArgumentException($"{file.FullName}: no such robot file");
            }

            var robot = RobotLoader.Load(file.FullName);
            var record = UnitFile.Load(path) ?? new UnitFile { Unit = parse.GetValue(unit)!, RobotFile = parse.GetValue(robotFile)!.ToString() };
            var options = new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(parse.GetValue(margin)) };
            var line = new BusLine(parse.GetValue(transport)!, file.FullName, options);
            if (line.Uri.Kind == LinkKind.Virtual)
            {
                throw new ArgumentException("--transport virtual: a virtual robot starts commissioned; serve a box of boards with robotctl bus-sim --pty --factory and give its serial: path");
            }

            var factoryBaud = ModuleParameters.BaudFromCode((int)ControlTable.Firmware["baud_rate"].Default);
            RobotConnection.CheckTransport(line.Transport(factoryBaud));
            using var client = new BusClient(new ReopenableLink(() => LinkFactory.Open(line.Transport(factoryBaud))), TimeProvider.System, line.Options);
            var setup = new CommissionSetup(robot, record, path, Console.In, parse.GetValue(yes), new CommissionClock(TimeProvider.System), (baud, id) =>
                ((ReopenableLink)client.Link).Released(() =>
                {
                    // The port released first: one process owns it, and its baud is the device's, not a descriptor's.
                    using var other = Open(line, baud);
                    return other.Ping(id, out _).Outcome == ReplyOutcome.Ok;
                }));
            return new Commissioner(setup, client, parse.InvocationConfiguration.Output).Run();
        }));
        return command;
    }

    private static BusClient Open(BusLine line, int baud)
    {
        RobotConnection.CheckTransport(line.Transport(baud));
        return new BusClient(LinkFactory.Open(line.Transport(baud)), TimeProvider.System, line.Options);
    }
}
