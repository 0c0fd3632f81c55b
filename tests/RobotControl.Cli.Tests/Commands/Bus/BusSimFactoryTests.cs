using System.Text.RegularExpressions;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// <c>robotctl bus-sim --factory [--unit-variation seed]</c> in a process of its own behind a pty: modules plugged in
/// one line at a time on its standard input, each at the factory ID, an ID written kept across a power cycle.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed partial class BusSimFactoryTests
{
    private static readonly TimeSpan Patience = RunProcess.Patience;
    private static readonly ControlTable Table = ControlTable.Firmware;

    private static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    private static byte FactoryId => (byte)Table["id"].Default;

    [Fact]
    public void A_box_of_boards_is_plugged_in_line_by_line_and_keeps_an_id_written_across_a_power_cycle()
    {
        using var sim = new RunProcess(typing: true, "bus-sim", Robot, "--pty", "--factory", "--unit-variation", "7");
        var started = sim.WaitFor("plug modules in on stdin", Patience);
        Assert.Contains($"from the factory (6 modules, 0 plugged in, each at id {FactoryId})", started, StringComparison.Ordinal);
        Assert.Equal(SimulatorProcess.Robot.Modules.Modules.Sum(m => m.Motors.Count), PotLine().Count(started)); // every pot's true curve, printed for a later calibration check
        using var client = new BusClient(LinkFactory.Open(Transport().Match(started).Value), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) });
        var found = new PingInfo[16];
        Assert.Equal(0, client.Discover(found));

        sim.Type("connect");
        sim.WaitFor($"connected module 1 (right shoulder): it answers at id {FactoryId}", Patience);
        Assert.Equal(1, client.Discover(found));
        Assert.Equal(FactoryId, found[0].Id);

        _ = client.Write(FactoryId, Table["id"].At(0), [21]); // it answers from its new ID
        sim.Type("power-cycle right.shoulder");
        sim.WaitFor("power-cycled module 1 (right shoulder): it answers at id 21", Patience);
        Assert.True(client.Ping(21, out _).Succeeded);

        sim.Type("connect");
        sim.WaitFor($"connected module 2 (right upper arm): it answers at id {FactoryId}", Patience);
        var n = client.Discover(found);
        Assert.Equal(new byte[] { FactoryId, 21 }, found.Take(n).Select(p => p.Id).Order());

        sim.Type("power-cycle left.forearm");
        sim.WaitFor("cannot power-cycle module 13 (left forearm): it is not plugged in (connect it first)", Patience);
        sim.Signal("TERM");
        Assert.Equal(0, sim.WaitForExit(Patience));
    }

    [Fact]
    public void Factory_options_that_cannot_be_are_refused_in_one_line()
    {
        Cli.AssertRefused(Cli.Run("bus-sim", Robot, "--pty", "--factory", "--baud", "3000000"), "--baud 3000000: modules from the factory run at the factory baud (1000000)");
        Cli.AssertRefused(Cli.Run("bus-sim", Robot, "--pty", "--connected", "2"), "--connected: only with --factory");
        Cli.AssertRefused(Cli.Run("bus-sim", Robot, "--pty", "--factory", "--connected", "7"), "--connected 7: LB-1.0 has 6 modules");
    }

    [GeneratedRegex(@"serial:\S+")]
    private static partial Regex Transport();

    [GeneratedRegex(@"^pot \S+: true adc_at_min [0-9.]+ adc_at_max [0-9.]+ bow_counts -?[0-9.]+ \(design ", RegexOptions.Multiline)]
    private static partial Regex PotLine();
}
