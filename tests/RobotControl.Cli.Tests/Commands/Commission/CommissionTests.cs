using System.Text.Json.Nodes;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Commission;

/// <summary>
/// <c>robotctl commission --yes</c> against <c>bus-sim --factory --unit-variation</c>, each in a process of its own,
/// the box of boards behind a pty: modules connected one at a time as the command asks (lines on bus-sim's stdin),
/// every module numbered, parameterised, verified and recorded; a power cut mid-way resumed; a refused write and two
/// modules at the default ID each one line.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class CommissionTests : IDisposable
{
    private static readonly TimeSpan Patience = RunProcess.Patience;
    private static readonly byte FactoryId = (byte)ControlTable.Firmware["id"].Default;
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    private static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void A_box_of_boards_connected_one_at_a_time_is_commissioned_and_discover_finds_it_as_recorded()
    {
        using var sim = StartSim(out var transport);
        using var commission = Commission(transport, "lb-0001");
        ConnectAsAsked(sim, commission, 1, 6);
        Assert.Equal(0, commission.WaitForExit(Patience));
        Assert.Contains("unit lb-0001 commissioned: 6 modules", commission.Output, StringComparison.Ordinal);

        var unit = JsonNode.Parse(File.ReadAllText(Path.Combine(_units, "lb-0001.json")))!.AsObject();
        var modules = unit["modules"]!.AsArray();
        Assert.Equal(new[] { 1, 2, 3, 11, 12, 13 }, modules.Select(m => (int)m!["id"]!).Order());
        Assert.All(modules, m => Assert.Equal((int)ControlTable.Firmware["firmware_version"].Default, (int)m!["firmware_version"]!));
        var expected = RobotControl.Modules.ModuleParameters.For(SimulatorProcess.Robot, SimulatorProcess.Robot.Modules.Modules.Single(m => m.Id == 11), ControlTable.Firmware).Count(p => p.Field.Name != "baud_rate");
        Assert.Equal(expected, modules.Single(m => (int)m!["id"]! == 11)!["parameters"]!.AsObject().Count);

        var discover = Cli.Run("discover", transport, "--robot", Robot, "--unit", "lb-0001", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
        Assert.Contains("unit lb-0001: 6 modules as commissioned", discover.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("UNIT ", discover.Output, StringComparison.Ordinal);

        // A parameter changed behind the unit file's back is reported, naming the module and the value.
        using (var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) }))
        {
            Assert.True(client.Write(12, ControlTable.Firmware["kp"].At(0), [1, 0]).Succeeded);
        }

        var changed = Cli.Run("discover", transport, "--robot", Robot, "--unit", "lb-0001", "--units", _units, "--margin-ms", "50");
        Assert.Equal(1, changed.Code);
        Assert.Contains("UNIT     module 12 (left upper arm): kp[0] is 1, the unit file says ", changed.Output, StringComparison.Ordinal);
    }

    [Fact]
    public void A_power_cut_mid_commissioning_loses_nothing_and_a_second_run_completes_the_unit()
    {
        using var sim = StartSim(out var transport);
        using (var first = Commission(transport, "lb-0002"))
        {
            ConnectAsAsked(sim, first, 1, 2);
            var third = Prompted(first, 3); // the left shoulder, the module with the most parameters
            sim.Type($"connect {third}");
            first.WaitFor($"now answers at id {third}", Patience);
            sim.Type($"disconnect {third}"); // the power goes, mid-way through its parameters or just after
            var waited = System.Diagnostics.Stopwatch.StartNew();
            while (!first.Output.Contains("run commission again", StringComparison.Ordinal) && !first.Output.Contains("connect module 4 of 6", StringComparison.Ordinal) && waited.Elapsed < Patience)
            {
                Thread.Sleep(50);
            }

            if (!first.Output.Contains("run commission again", StringComparison.Ordinal))
            {
                first.Signal("INT"); // the cut came after the module was recorded: the operator stops it (Ctrl+C)
            }

            Assert.NotEqual(0, first.WaitForExit(Patience));
            sim.Type($"connect {third}"); // power back: its FRAM kept whatever was written
            sim.WaitFor($"connected module {third} ", Patience);
        }

        var recorded = Modules("lb-0002");
        Assert.Equal(new[] { 2, 3 }, recorded.Take(2));
        using var second = Commission(transport, "lb-0002");
        second.WaitFor("module 1 of 6 (right upper arm, id 2): done", Patience);
        ConnectAsAsked(sim, second, 4, 6); // the first three are plugged in: done, or redone from the start
        Assert.Equal(0, second.WaitForExit(Patience));
        Assert.True(recorded.Contains(11) || second.Output.Contains("module 3 of 6 (left shoulder, id 11): answers at its ID already (a commissioning stopped halfway): writing its parameters again", StringComparison.Ordinal), second.Output);
        Assert.Equal(new[] { 1, 2, 3, 11, 12, 13 }, Modules("lb-0002").Order());
        var discover = Cli.Run("discover", transport, "--robot", Robot, "--unit", "lb-0002", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
    }

    [Fact]
    public void A_module_cut_off_halfway_through_its_parameters_is_redone_on_the_next_run()
    {
        using var sim = StartSim(out var transport);
        using (var first = Commission(transport, "lb-0006"))
        {
            ConnectAsAsked(sim, first, 1, 2);
            Assert.Equal(11, Prompted(first, 3));
            first.Signal("INT"); // the operator stops it (Ctrl+C) while it waits for the left shoulder
            Assert.NotEqual(0, first.WaitForExit(Patience));
        }

        // The left shoulder as a stopped run leaves it: numbered, one parameter written wrong, the rest at their
        // defaults; then the power goes off and on (its FRAM keeps all of it).
        sim.Type("connect 11");
        sim.WaitFor("connected module 11 ", Patience);
        using (var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) }))
        {
            _ = client.Write(FactoryId, ControlTable.Firmware["id"].At(0), [11]); // it answers from id 11 at once
            Assert.True(client.Write(11, ControlTable.Firmware["kp"].At(1), [7, 0]).Succeeded);
        }

        sim.Type("power-cycle 11");
        sim.WaitFor("power-cycled module 11 (left shoulder): it answers at id 11", Patience);
        Assert.Equal(new[] { 2, 3 }, Modules("lb-0006"));

        using var second = Commission(transport, "lb-0006");
        second.WaitFor("module 3 of 6 (left shoulder, id 11): answers at its ID already (a commissioning stopped halfway): writing its parameters again", Patience);
        ConnectAsAsked(sim, second, 4, 6);
        Assert.Equal(0, second.WaitForExit(Patience));
        Assert.Contains("module 2 of 6 (right forearm, id 3): done", second.Output, StringComparison.Ordinal);
        var discover = Cli.Run("discover", transport, "--robot", Robot, "--unit", "lb-0006", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
        var kp = JsonNode.Parse(File.ReadAllText(Path.Combine(_units, "lb-0006.json")))!["modules"]!.AsArray().Single(m => (int)m!["id"]! == 11)!["parameters"]!["kp[1]"]!;
        Assert.NotEqual(7, (int)kp);
    }

    [Fact]
    public void A_module_that_refuses_a_write_stops_commissioning_with_one_line_naming_it_and_what_to_do()
    {
        using var sim = StartSim(out var transport);
        sim.Type("connect 2");
        sim.WaitFor("connected module 2 ", Patience);
        using (var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) }))
        {
            Assert.True(client.Write(FactoryId, ControlTable.Firmware["torque_enable"].At(0), [1]).Succeeded);
        }

        using var commission = Commission(transport, "lb-0003");
        Assert.Equal(2, commission.WaitForExit(Patience));
        Assert.True(commission.Output.Contains($"commissioning right upper arm: module {FactoryId}: writing id[0] = 2 failed (Ok, 0x07 access error)", StringComparison.Ordinal), commission.Output);
        Assert.Contains("turn torque off first", commission.Output, StringComparison.Ordinal);
        Assert.False(File.Exists(Path.Combine(_units, "lb-0003.json")), "nothing recorded for a module not done");
    }

    [Fact]
    public void A_robot_file_that_switches_a_protection_off_is_refused_before_any_module_is_touched()
    {
        var robot = Cli.CopyRobot(_units, json => json["modules"]!["watchdog_ms"] = 0);
        var refused = Cli.Run("commission", robot, "--transport", "serial:/dev/null", "--unit", "lb-0004", "--units", _units);
        Cli.AssertRefused(refused, "$.modules.watchdog_ms: is 0, which switches the modules' bus watchdogs off");
        Assert.Equal(2, refused.Code);
        Assert.False(File.Exists(Path.Combine(_units, "lb-0004.json")), "no unit file for a refused robot file");
    }

    [Fact]
    public void Two_modules_at_the_default_id_are_detected_and_explained_in_one_line()
    {
        using var sim = StartSim(out var transport);
        sim.Type("connect 2");
        sim.Type("connect 3");
        sim.WaitFor("connected module 3 ", Patience);
        using var commission = Commission(transport, "lb-0005");
        commission.WaitFor($"two modules answer at ID {FactoryId}: unplug all but one", Patience);
        sim.Type("disconnect 3");
        commission.WaitFor("module 1 of 6 (right upper arm, id 2): now answers at id 2", Patience);
        commission.Signal("INT");
        commission.WaitForExit(Patience);
    }

    [Fact]
    public void Interactively_each_module_is_asked_for_and_looked_for_when_the_operator_presses_Enter()
    {
        using var sim = StartSim(out var transport);
        using var commission = new RunProcess(typing: true, "commission", Robot, "--transport", transport, "--unit", "lb-0007", "--units", _units, "--margin-ms", "50");
        commission.WaitFor("connect module 1 of 6 (right upper arm, id 2), then press Enter", Patience);
        commission.Type(string.Empty); // Enter with nothing plugged in
        commission.WaitFor($"no module answers at id {FactoryId}: check that module 1 of 6 (right upper arm, id 2) is plugged in and powered, then press Enter", Patience);
        sim.Type("connect 2");
        sim.WaitFor("connected module 2 ", Patience);
        commission.Type(string.Empty);
        commission.WaitFor("connect module 2 of 6 (right forearm, id 3), then press Enter", Patience);
        Assert.Equal(new[] { 2 }, Modules("lb-0007"));
        commission.Signal("INT");
        Assert.NotEqual(0, commission.WaitForExit(Patience));
    }

    [Fact]
    public void Bad_input_is_one_line_and_exit_2()
    {
        var missing = Cli.Run("commission", Path.Combine(_units, "none.json"), "--transport", "serial:/dev/null", "--unit", "u", "--units", _units);
        Cli.AssertRefused(missing, "no such robot file");
        Assert.Equal(2, missing.Code);
        var path = Cli.Run("commission", Robot, "--transport", "serial:/dev/null", "--unit", "a/b", "--units", _units);
        Cli.AssertRefused(path, "--unit 'a/b': a unit name is a file name (no path separator)");
        Assert.Equal(2, path.Code);
        var transport = Cli.Run("commission", Robot, "--transport", "serial:/dev/rc-no-such-port", "--unit", "u", "--units", _units);
        Cli.AssertRefused(transport, "/dev/rc-no-such-port");
        Assert.Equal(2, transport.Code);
    }

    private static RunProcess StartSim(out string transport) => FactoryBench.StartSim(out transport);

    private RunProcess Commission(string transport, string unit, string? robot = null) =>
        new("commission", robot ?? Robot, "--transport", transport, "--unit", unit, "--units", _units, "--yes", "--margin-ms", "50");

    private static void ConnectAsAsked(RunProcess sim, RunProcess commission, int from, int to) => FactoryBench.ConnectAsAsked(sim, commission, from, to);

    private static int Prompted(RunProcess commission, int k) => FactoryBench.Prompted(commission, k);

    private List<int> Modules(string unit)
    {
        var path = Path.Combine(_units, unit + ".json");
        return File.Exists(path) ? [.. JsonNode.Parse(File.ReadAllText(path))!["modules"]!.AsArray().Select(m => (int)m!["id"]!)] : [];
    }
}
