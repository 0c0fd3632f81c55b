using System.Text.RegularExpressions;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Commission;

/// <summary>
/// A box of boards on the bench for the bring-up tests: <c>bus-sim --factory --unit-variation 3</c> in a process of
/// its own behind a pty, modules connected as a command asks for them, and a unit commissioned on it.
/// </summary>
internal static partial class FactoryBench
{
    /// <summary>The unit variation seed the bring-up tests use.</summary>
    public const int UnitSeed = 3;

    private static readonly TimeSpan Patience = RunProcess.Patience;

    public static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    /// <summary>Starts the box of boards; <paramref name="transport"/> is its pty.</summary>
    public static RunProcess StartSim(out string transport)
    {
        var sim = new RunProcess(typing: true, "bus-sim", Robot, "--pty", "--factory", "--unit-variation", UnitSeed.ToString(System.Globalization.CultureInfo.InvariantCulture));
        transport = Transport().Match(sim.WaitFor("plug modules in on stdin", Patience)).Value;
        return sim;
    }

    /// <summary>Commissions every module as unit <paramref name="unit"/> under <paramref name="units"/>, connecting each as asked.</summary>
    public static void Commission(RunProcess sim, string transport, string unit, string units)
    {
        using var commission = new RunProcess("commission", Robot, "--transport", transport, "--unit", unit, "--units", units, "--yes", "--margin-ms", "50");
        ConnectAsAsked(sim, commission, 1, 6);
        Assert.Equal(0, commission.WaitForExit(Patience));
    }

    /// <summary>Connects modules <paramref name="from"/>..<paramref name="to"/> (the command's numbering), each as the command asks for it.</summary>
    public static void ConnectAsAsked(RunProcess sim, RunProcess commission, int from, int to)
    {
        for (var k = from; k <= to; k++)
        {
            var id = Prompted(commission, k);
            sim.Type($"connect {id}");
            sim.WaitFor($"connected module {id} ", Patience);
        }
    }

    /// <summary>The robot-file ID of module <paramref name="k"/> the command asks to connect.</summary>
    public static int Prompted(RunProcess commission, int k)
    {
        var output = commission.WaitFor($"connect module {k} of 6 (", Patience);
        return int.Parse(Regex.Match(output, $@"connect module {k} of 6 \([^)]*, id (\d+)\)").Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
    }

    [GeneratedRegex(@"serial:\S+")]
    private static partial Regex Transport();
}
