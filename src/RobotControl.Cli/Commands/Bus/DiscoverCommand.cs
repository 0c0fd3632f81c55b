using System.CommandLine;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl discover &lt;transport&gt; [--robot file]</c>: broadcast-pings the bus; with a robot file, reports
/// missing, unknown and mismatched modules and parameters that differ from the file; <c>--clear-faults</c> names and
/// clears latched module errors. Exit 1 when anything differs.
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
        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
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

                var mismatches = session.Robot.CheckParameters();
                foreach (var m in mismatches)
                {
                    output.WriteLine($"PARAM    {m}");
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
