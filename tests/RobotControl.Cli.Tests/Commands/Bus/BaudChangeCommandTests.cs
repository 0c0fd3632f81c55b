using RobotControl.Bus.Client;
using RobotControl.Cli.Commands.Bus;
using RobotControl.Definitions.Loading;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// A baud change end to end on the virtual LB-1.0 served on a pty (real firmware; the simulated line follows the baud
/// the host sets on its port): <c>params set --field baud_rate</c> moves every module and then the host, verified by
/// ping; <c>discover --scan-bauds</c> finds modules at any supported baud and brings them back to the robot file's.
/// </summary>
[Collection(PtyBus.Collection)]
public sealed class BaudChangeCommandTests
{
    private static readonly byte[] Ids = [1, 2, 3, 11, 12, 13];

    [Fact]
    public void An_unconfirmed_baud_change_says_what_would_happen_and_writes_nothing()
    {
        using var bus = new PtyBus();

        var result = bus.Run("params set", "--field", "baud_rate", "--value", "0");

        Cli.AssertRefused(result, "--yes: this writes baud_rate 0 (9600 baud) into all 6 modules of");
        Assert.Contains("re-opens serial", result.Error, StringComparison.Ordinal);
        Assert.All(Ids, id => Assert.Equal(3, bus.Read(id, "baud_rate", 0)));
    }

    [Fact]
    public void A_motor_given_with_the_baud_is_refused()
    {
        using var bus = new PtyBus();

        Cli.AssertRefused(bus.Run("params set", "--field", "baud_rate", "--value", "4", "--motor", "1", "--yes"), "--motor: baud_rate is one value per module");
        Assert.Equal(3, bus.Read(1, "baud_rate", 0));
    }

    [Fact]
    public void A_change_to_the_baud_every_module_already_answers_at_writes_nothing()
    {
        using var bus = new PtyBus();

        var (code, output, error) = bus.Run("params set", "--field", "baud_rate", "--value", "3", "--yes");

        Assert.True(code == 0, output + error);
        Assert.Contains("every module already answers at 1000000 baud (baud_rate 3); nothing was written", output, StringComparison.Ordinal);
    }

    [Fact]
    public void A_baud_change_with_a_module_left_behind_is_refused_before_anything_is_written()
    {
        using var bus = new PtyBus();
        bus.Write(12, "baud_rate", 2); // module 12 now answers at 115200 baud only

        var result = bus.Run("params set", "--field", "baud_rate", "--value", "4", "--yes");

        Cli.AssertRefused(result, "MISSING  id  12");
        Assert.Contains("nothing was written", result.Error, StringComparison.Ordinal);
        Assert.All(Ids.Where(id => id != 12), id => Assert.Equal(3, bus.Read(id, "baud_rate", 0)));
    }

    [Fact]
    public void Writing_the_robot_file_at_another_baud_than_the_files_is_refused()
    {
        using var bus = new PtyBus();

        var result = bus.RunAt(2_000_000, "params set", "--from-robot-file");

        Cli.AssertRefused(result, "the robot file says modules.baud = 1000000 but the bus runs at 2000000 baud");
    }

    [Fact]
    public void A_confirmed_change_to_the_lowest_baud_moves_every_module_and_the_scan_brings_them_all_back()
    {
        using var bus = new PtyBus();
        string[] slow = ["--margin-ms", "500"]; // at 9600 baud a frame takes ~12 ms, and the simulation may slip behind on a loaded machine

        var (code, output, error) = bus.Run("params set", ["--field", "baud_rate", "--value", "0", "--yes", .. slow]);

        Assert.True(code == 0, output + error);
        Assert.Contains("baud changed: modules 1, 2, 3, 11, 12, 13 answer a ping at 9600 baud", output, StringComparison.Ordinal);
        Assert.Contains("the robot file still says modules.baud = 1000000", output, StringComparison.Ordinal);
        Assert.All(Ids, id => Assert.Equal(0, bus.Read(id, "baud_rate", 0, baud: 9600)));
        Assert.False(bus.Answers(1, 1_000_000));

        var scan = bus.Run("discover", ["--scan-bauds", .. slow]);
        Assert.Equal(1, scan.Code);
        Assert.Contains("at    9600 baud: id 1 ", scan.Output, StringComparison.Ordinal);
        Assert.Contains("at 1000000 baud: no module", scan.Output, StringComparison.Ordinal);
        Assert.Contains("--scan-bauds --yes", scan.Output, StringComparison.Ordinal);

        AssertBroughtBack(bus, "6 of 6 module(s) brought back to 1000000 baud (verified by ping)", slow);
    }

    [Fact]
    public void The_scan_finds_one_module_at_another_baud_offers_the_way_back_and_brings_it_back()
    {
        using var bus = new PtyBus();
        bus.Write(2, "baud_rate", 6); // module 2 now answers at 4 Mbaud only
        Assert.Equal(1, bus.Run("discover").Code);

        var scan = bus.Run("discover", "--scan-bauds");

        Assert.Equal(1, scan.Code);
        Assert.Contains("at 4000000 baud: id 2 (model", scan.Output, StringComparison.Ordinal);
        Assert.Contains("ELSEWHERE id   2  right upper arm: answers at 4000000 baud, the robot file says 1000000", scan.Output, StringComparison.Ordinal);
        Assert.Contains($"to bring it back to 1000000 baud run: robotctl discover {bus.Transport}?baud=1000000 --robot {bus.RobotFile} --scan-bauds --yes", scan.Output, StringComparison.Ordinal);
        Assert.Equal(6, bus.Read(2, "baud_rate", 0, baud: 4_000_000)); // the offer alone changes nothing

        AssertBroughtBack(bus, "1 of 1 module(s) brought back to 1000000 baud");
    }

    [Fact]
    public void A_module_that_did_not_follow_is_named_with_where_it_is_and_the_printed_command_brings_the_bus_back()
    {
        using var bus = new PtyBus();
        foreach (var id in Ids.Where(id => id != 12))
        {
            bus.Write(id, "baud_rate", 4); // as if module 12 had missed the ACTION of a change to 2 Mbaud
        }

        var line = new BusLine(bus.Transport, bus.RobotFile, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(100) });
        var output = new StringWriter();

        var code = BaudChange.Verify(line, RobotLoader.Load(bus.RobotFile), 1_000_000, 2_000_000, output);

        var text = output.ToString();
        Assert.Equal(1, code);
        Assert.Contains("modules 1, 2, 3, 11, 13 answer at 2000000 baud", text, StringComparison.Ordinal);
        Assert.Contains("NOT CHANGED module 12 \"left upper arm\": still answers at 1000000 baud, not at 2000000", text, StringComparison.Ordinal);
        var command = text.Split('\n').Single(l => l.StartsWith("the bus is split", StringComparison.Ordinal));
        var args = command[(command.IndexOf("robotctl ", StringComparison.Ordinal) + "robotctl ".Length)..].Trim().Split(' ');
        var back = Cli.Run([.. args, "--margin-ms", "300"]); // the simulation may slip behind real time on a loaded machine
        Assert.True(back.Code == 0, back.Output + back.Error);
        Assert.Contains("5 of 5 module(s) brought back to 1000000 baud", back.Output, StringComparison.Ordinal);
        Assert.Equal(0, bus.Run("discover").Code);
    }

    [Theory]
    [InlineData("virtual:", "bus-sim --pty")]
    [InlineData("tcp:127.0.0.1:9", "set on the bridge")]
    public void Transports_whose_host_side_cannot_change_baud_are_refused(string kind, string expected)
    {
        var transport = kind == "virtual:" ? kind + Cli.RepoFile("hardware/robots/lb-1.0.json") : kind;

        Cli.AssertRefused(Cli.Run("discover", transport, "--scan-bauds"), expected);
    }

    [Fact]
    public void Yes_without_scan_bauds_is_refused() =>
        Cli.AssertRefused(Cli.Run("discover", "virtual:" + Cli.RepoFile("hardware/robots/lb-1.0.json"), "--yes"), "--yes: only with --scan-bauds");

    /// <summary><c>discover --scan-bauds --yes</c> says <paramref name="expected"/>, and a plain discover then finds every module as configured.</summary>
    private static void AssertBroughtBack(PtyBus bus, string expected, params string[] options)
    {
        var back = bus.Run("discover", ["--scan-bauds", "--yes", .. options]);
        Assert.True(back.Code == 0, back.Output + back.Error);
        Assert.Contains(expected, back.Output, StringComparison.Ordinal);
        var normal = bus.Run("discover");
        Assert.True(normal.Code == 0, normal.Output + normal.Error);
        Assert.Contains("all 6 modules as configured", normal.Output, StringComparison.Ordinal);
    }
}
