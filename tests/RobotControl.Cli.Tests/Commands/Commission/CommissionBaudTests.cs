using System.Text.Json.Nodes;
using RobotControl.Bus.Protocol;
using RobotControl.Cli.Tests.Commands.Run;
using RobotControl.Modules;

namespace RobotControl.Cli.Tests.Commands.Commission;

/// <summary>
/// <c>robotctl commission --yes</c> with a robot file whose bus runs at another baud than the factory's (2 Mbaud for
/// the control table's default 1 Mbaud) against <c>bus-sim --factory</c> in another process behind a pty: each module
/// is moved to the new baud last and found there, the next fresh module is still found at the factory baud, and
/// <c>discover --unit</c> at the new baud finds every module as recorded.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class CommissionBaudTests : IDisposable
{
    private const int Baud = 2_000_000;
    private static readonly TimeSpan Patience = RunProcess.Patience;
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void A_robot_file_at_another_baud_is_commissioned_to_it_and_discover_at_that_baud_finds_the_unit_as_recorded()
    {
        var factory = ModuleParameters.BaudFromCode((int)ControlTable.Firmware["baud_rate"].Default);
        Assert.NotEqual(Baud, factory);
        var robot = Cli.CopyRobot(_units, json => json["modules"]!["baud"] = Baud);
        using var sim = FactoryBench.StartSim(out var transport);
        using (var commission = new RunProcess("commission", robot, "--transport", transport, "--unit", "lb-0008", "--units", _units, "--yes", "--margin-ms", "50"))
        {
            FactoryBench.ConnectAsAsked(sim, commission, 1, 6);
            Assert.True(commission.WaitForExit(Patience) == 0, commission.Output);
            Assert.Contains("unit lb-0008 commissioned: 6 modules", commission.Output, StringComparison.Ordinal);
        }

        var modules = JsonNode.Parse(File.ReadAllText(Path.Combine(_units, "lb-0008.json")))!["modules"]!.AsArray();
        Assert.Equal(new[] { 1, 2, 3, 11, 12, 13 }, modules.Select(m => (int)m!["id"]!).Order());
        Assert.All(modules, m =>
        {
            Assert.Equal(ModuleParameters.BaudCode(Baud), (int)m!["parameters"]!["baud_rate"]!);
            Assert.Equal((int)ControlTable.Firmware["firmware_version"].Default, (int)m["firmware_version"]!);
        });

        var discover = Cli.Run("discover", $"{transport.Split('?')[0]}?baud={Baud}", "--robot", robot, "--unit", "lb-0008", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
        Assert.Contains("unit lb-0008: 6 modules as commissioned", discover.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("UNIT ", discover.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("PARAM ", discover.Output, StringComparison.Ordinal);
        Assert.Contains("all 6 modules as configured", discover.Output, StringComparison.Ordinal);

        // At the factory baud nothing answers any more: every module moved.
        var old = Cli.Run("discover", $"{transport.Split('?')[0]}?baud={factory}", "--robot", robot, "--margin-ms", "50");
        Assert.NotEqual(0, old.Code);
    }
}
