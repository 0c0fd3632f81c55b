using System.CommandLine;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl home &lt;transport&gt;</c>: homes every motor from its pot (motors off) and prints, per motor, whether it
/// was homed and verified, with pot and position side by side. Exit code 1 if a module is missing or a motor was not homed.
/// </summary>
internal sealed class HomeCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var command = new Command("home", "Home every motor from its joint potentiometer.");
        var busOptions = new BusOptions(command);
        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            return busOptions.Run(parse, session =>
            {
                var bus = session.RequireRobot();
                var report = bus.Discover();
                foreach (var problem in report.Problems)
                {
                    output.WriteLine(problem.Line);
                }

                var results = bus.Home();
                foreach (var r in results)
                {
                    output.WriteLine(r.ToString());
                }

                var failed = results.Count(r => !r.Succeeded);
                output.WriteLine(failed == 0
                    ? $"{results.Count} motors homed from their pots"
                    : $"{failed} of {results.Count} motors NOT homed (see above)");
                return report.Missing.Count == 0 && failed == 0 ? 0 : 1;
            });
        });
        return command;
    }
}
