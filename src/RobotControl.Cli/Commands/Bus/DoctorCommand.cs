using System.CommandLine;
using RobotControl.Cli.Options;
using RobotControl.Host.Realtime;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl doctor &lt;transport&gt; [--latency 10s]</c>: what the real-time path depends on (latency timer,
/// low-latency flag, baud error, real-time priority, CPU governor, hypervisor steal and, with <c>--latency</c>, how late
/// the machine wakes a SCHED_FIFO thread) and what to change. Exit 1 when something should change.
/// </summary>
internal sealed class DoctorCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var transport = new Argument<string>("transport") { Description = "The bus, e.g. serial:/dev/ttyUSB0?baud=1000000 or usb:0403:6014" };
        var latency = CliOption.Duration("--latency", "Also measure how late this machine wakes a SCHED_FIFO thread, for this long (cyclictest; 0: skip)", TimeSpan.Zero, TimeSpan.FromHours(1), TimeSpan.Zero);
        var command = new Command("doctor", "Check a port and this machine for real-time use, and say what to change.");
        command.Arguments.Add(transport);
        command.Options.Add(latency);
        command.SetAction(parse => Run(parse.GetValue(transport)!, "/sys", parse.GetValue(latency), parse.InvocationConfiguration.Output, parse.InvocationConfiguration.Error));
        return command;
    }

    /// <summary>Prints the findings; 0: nothing to change, 1: advice given, 2: bad transport.</summary>
    internal static int Run(string transport, string sysRoot, TimeSpan latencyProbe, TextWriter output, TextWriter error)
    {
        IReadOnlyList<DoctorFinding> findings;
        try
        {
            findings = Doctor.Examine(transport, sysRoot, latencyProbe: latencyProbe);
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
