using System.CommandLine;
using RobotControl.Bus.Client;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Commands.Bus;
using RobotControl.Cli.Commands.Commission;
using RobotControl.Cli.Commands.Run;
using RobotControl.Cli.Options;
using RobotControl.Definitions.Loading;
using RobotControl.Host.Session;
using RobotControl.Robot.Calibration;
using RobotControl.Robot.Commissioning;

namespace RobotControl.Cli.Commands.Calibrate;

/// <summary>
/// <c>robotctl calibrate pots &lt;robot&gt; --transport &lt;t&gt; --unit &lt;name&gt; [--yes] [--joints a,b] [--redo]</c>:
/// measures a commissioned unit's pot curves against the Hall counts, writes each motor's table into its module and
/// the unit file, and verifies it with a pot/encoder sweep (<see cref="PotCalibrationRun"/>). Run again after any
/// stop, it skips the motors the unit file has as calibrated and verified.
/// </summary>
internal sealed class CalibrateCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var robotFile = new Argument<FileInfo>("robot") { Description = "The robot data file the unit is built to, e.g. hardware/robots/lb-1.0.json" };
        var transport = new Option<string>("--transport") { Description = "The bus, e.g. serial:/dev/ttyUSB0 (opened at the robot file's baud)", Required = true };
        var unit = new Option<string>("--unit") { Description = "The commissioned unit: its record is <units>/<name>.json", Required = true };
        var units = new Option<DirectoryInfo>("--units") { Description = $"Directory of unit files (default {CommissionCommand.DefaultUnitsDirectory})" };
        var yes = new Option<bool>("--yes") { Description = "Non-interactive: take each arm as in its fixture pose without asking for Enter" };
        var joints = new Option<string>("--joints") { Description = "Only these motors, comma-separated: arm.joint (right.elbow) or a joint name (elbow, both arms)" };
        var redo = new Option<bool>("--redo") { Description = "Calibrate motors the unit file has as calibrated and verified again" };
        var margin = CliOption.Number("--margin-ms", "Reply timeout beyond the wire time, ms (USB adapters: their latency timer + 1)", 0.0, 1000.0, 3.0);
        var pots = new Command("pots", "Measure each pot against the Hall counts (the arm in its fixture pose, each joint swept slowly through its range), write the fitted table to the module and the unit file, verify it with a pot/encoder sweep; resumable.");
        pots.Arguments.Add(robotFile);
        foreach (var o in new Option[] { transport, unit, units, yes, joints, redo, margin })
        {
            pots.Options.Add(o);
        }

        pots.SetAction(parse => BusOptions.Guard(parse, () =>
        {
            var file = parse.GetValue(robotFile)!;
            var directory = parse.GetValue(units)?.FullName ?? CommissionCommand.DefaultUnitsDirectory;
            var path = UnitFile.PathOf(directory, parse.GetValue(unit)!);
            if (!file.Exists)
            {
                throw new ArgumentException($"{file.FullName}: no such robot file");
            }

            var robot = RobotLoader.Load(file.FullName);
            var record = UnitFile.Load(path) ?? throw new ArgumentException($"--unit {parse.GetValue(unit)}: no unit file {path}; commission the unit first (robotctl commission)");
            var selection = PotSelection.Parse(robot, parse.GetValue(joints));
            var line = new BusLine(parse.GetValue(transport)!, file.FullName, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(parse.GetValue(margin)) });
            if (line.Uri.Kind == LinkKind.Virtual)
            {
                throw new ArgumentException("--transport virtual: the in-process virtual robot's pots follow the design curves; serve a unit with robotctl bus-sim --pty --unit-variation <seed> and give its serial: path");
            }

            var baudTransport = line.Transport(robot.Modules.BaudRate);
            RobotConnection.CheckTransport(baudTransport);
            using var client = new BusClient(LinkFactory.Open(baudTransport), TimeProvider.System, line.Options);
            using var signals = new StopSignals(parse.InvocationConfiguration.Error, "motors off (read back), then the calibration stops");
            var setup = new PotCalibrationSetup(robot, record, path, Console.In, parse.GetValue(yes), selection, parse.GetValue(redo), new PotCalibrationOptions());
            return new PotCalibrationRun(setup, client, parse.InvocationConfiguration.Output, signals.Token).Run();
        }));
        var command = new Command("calibrate", "Calibrate a commissioned unit's sensors.");
        command.Subcommands.Add(pots);
        return command;
    }
}
