using System.CommandLine;
using RobotControl.Host.Realtime;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl doctor &lt;transport&gt;</c>: what the real-time path depends on (latency timer, low-latency flag, baud
/// error, real-time priority, CPU governor) and what to change. Exit 1 when something should change.
/// </summary>
internal sealed class DoctorCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var transport = new Argument<string>("transport") { Description = "The bus, e.g. serial:/dev/ttyUSB0?baud=1000000 or usb:0403:6014" };
        var command = new Command("doctor", "Check a port and this machine for real-time use, and say what to change.");
        command.Arguments.Add(transport);
        command.SetAction(parse => Run(parse.GetValue(transport)!, "/sys", parse.InvocationConfiguration.Output, parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Prints the findings; 0: nothing to change, 1: advice given, 2: bad transport.</summary>
    internal static int Run(string transport, string sysRoot, TextWriter output, TextWriter error)
    {
        IReadOnlyList<DoctorFinding> findings;
        try
        {
            findings = Doctor.Examine(transport, sysRoot);
        }
        catch (Exception ex) when (ex is FormatException or IOException)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        foreach (var f in findings)
        {
            output.WriteLine($"{(f.Advice is null ? "ok  " : "fix ")} {f.Check}: {f.Found}");
            if (f.Advice is not null)
            {
                output.WriteLine($"       -> {f.Advice}");
            }
        }

        return findings.Any(f => f.Advice is not null) ? 1 : 0;
    }
}
