using System.CommandLine;
using RobotControl.Cli.Commands.Commission;
using RobotControl.Robot.Commissioning;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl discover &lt;transport&gt; [--robot file]</c>: broadcast-pings the bus; with a robot file, reports
/// missing, unknown and mismatched modules and parameters that differ from the file; <c>--clear-faults</c> names and
/// clears latched module errors. Exit 1 when anything differs.
/// <c>--scan-bauds [--yes]</c>: looks at every supported baud instead (<see cref="BaudScan"/>).
/// </summary>
internal sealed class DiscoverCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var command = new Command("discover", "Find the modules on a bus and compare them with the robot file.");
        var busOptions = new BusOptions(command);
        var clearFaults = new Option<bool>("--clear-faults") { Description = "With a robot file: say which modules have a latched error (e.g. a tripped bus watchdog), then clear it" };
        command.Options.Add(clearFaults);
        var scanBauds = new Option<bool>("--scan-bauds") { Description = "Look for modules at every baud the control table supports; with --robot, offer to bring strays back to the file's baud" };
        var yes = new Option<bool>("--yes") { Description = "With --scan-bauds: bring the robot's modules found at another baud back to the robot file's baud" };
        var unit = new Option<string?>("--unit") { Description = "With a robot file: also compare every module with this unit's file (ID, firmware version, the parameters commissioning wrote)" };
        var units = new Option<DirectoryInfo?>("--units") { Description = $"Directory of unit files (default {CommissionCommand.DefaultUnitsDirectory})" };
        command.Options.Add(scanBauds);
        command.Options.Add(yes);
        command.Options.Add(unit);
        command.Options.Add(units);
        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            if (parse.GetValue(scanBauds) || parse.GetValue(yes))
            {
                return BusOptions.Guard(parse, () => parse.GetValue(scanBauds)
                    ? BaudScan.Run(busOptions.Line(parse), parse.GetValue(yes), output)
                    : throw new ArgumentException("--yes: only with --scan-bauds (it confirms bringing modules back to the robot file's baud)"));
            }

            return busOptions.Run(parse, session =>
            {
                if (session.Robot is null)
                {
                    var found = new RobotControl.Bus.Client.PingInfo[253];
                    var n = session.Client.Discover(found);
                    foreach (var p in found.AsSpan(0, n))
                    {
                        output.WriteLine($"id {p.Id,3}  model {p.ModelNumber}  firmware {p.FirmwareVersion}");
                    }

                    output.WriteLine($"{n} module(s) answered on {session.Client.Link.Description}");
                    return 0;
                }

                var report = session.Robot.Discover();
                foreach (var line in report.Lines())
                {
                    output.WriteLine(line);
                }

                if (parse.GetValue(clearFaults))
                {
                    _ = LatchedFaults.Clear(session.Robot, output);
                }

                var name = parse.GetValue(unit);
                var path = name is null ? null : UnitFile.PathOf(parse.GetValue(units)?.FullName ?? CommissionCommand.DefaultUnitsDirectory, name);
                var recorded = path is null ? null : UnitFile.Load(path) ?? throw new ArgumentException($"--unit {name}: no unit file {path} (robotctl commission writes it)");
                var differ = session.Robot.CheckParameters();
                var calibrated = recorded is null ? [] : UnitCheck.Calibrated(differ, recorded);
                var mismatches = differ.Except(calibrated).ToList();
                foreach (var m in mismatches)
                {
                    output.WriteLine($"PARAM    {m}");
                }

                if (calibrated.Count > 0)
                {
                    output.WriteLine($"POTCAL   {calibrated.Count} pot_cal values are unit {name}'s calibrated pot tables, not the robot file's design curves (as recorded)");
                }

                if (recorded is not null)
                {
                    var differences = UnitCheck.Differences(session.Client, recorded);
                    foreach (var d in differences)
                    {
                        output.WriteLine($"UNIT     {d}");
                    }

                    output.WriteLine(differences.Count == 0 ? $"unit {name}: {recorded.Modules.Count} modules as commissioned" : $"unit {name}: {differences.Count} differences from {path}");
                    if (differences.Count > 0)
                    {
                        return 1;
                    }
                }

                output.WriteLine(report.AllAsConfigured && mismatches.Count == 0
                    ? $"all {report.Present.Count} modules as configured"
                    : $"{report.Missing.Count} missing, {report.Unknown.Count} unknown, {report.Mismatched.Count} mismatched, {mismatches.Count} parameters differ");
                return report.AllAsConfigured && mismatches.Count == 0 ? 0 : 1;
            });
        });
        return command;
    }
}
