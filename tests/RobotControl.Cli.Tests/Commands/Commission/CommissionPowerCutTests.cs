using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Cli.Tests.Commands.Calibrate;
using RobotControl.Modules;
using RobotControl.Robot.Commissioning;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;
using Xunit.Abstractions;

namespace RobotControl.Cli.Tests.Commands.Commission;

/// <summary>
/// A power cut in the middle of a FRAM write of one parameter (<see cref="VirtualRobot.CutPowerAfterFramBytes"/>: the
/// module loses power 100 bytes into the record it is writing) while <see cref="Commissioner"/> writes a fresh
/// module's parameters, on the in-process box of boards (the real firmware): the write is never acknowledged, the
/// commissioning stops with one line naming the module, nothing is recorded; powered again, the module restarts with
/// the parameters it had before the torn write (not defaults, not a mix), and a second run writes them all again and
/// records the module as the robot file says.
/// </summary>
public sealed class CommissionPowerCutTests(ITestOutputHelper log) : IDisposable
{
    private const byte Module = 2; // the right upper arm, the first module the commissioning asks for
    private static readonly ControlTable Table = ControlTable.Firmware;
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void A_power_cut_mid_way_through_a_parameters_FRAM_write_loses_that_write_whole_and_a_second_run_completes_the_module()
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(ShippedRobots.Lb, clock, new VirtualRobotOptions { Factory = true });
        sim.Connect(Module);
        var path = Path.Combine(_units, "lb-0401.json");
        var unit = new UnitFile { Unit = "lb-0401", RobotFile = "lb-1.0.json" };
        foreach (var other in sim.Definition.Modules.Modules.Where(m => m.Id != Module))
        {
            unit.Modules.Add(new UnitModule { Id = other.Id, Name = other.Name, ModelNumber = 0, FirmwareVersion = 3, Parameters = [] }); // done before: only the upper arm is left
        }

        unit.Save(path, clock.GetUtcNow());
        var (start, end) = Table.PersistentArea;
        var before = new byte[end - start];
        var torn = default(System.Text.RegularExpressions.Match);
        var frames = 0;
        var link = new FaultOnCue(sim.OpenLink(), () => ++frames > 15, () =>
        {
            sim.PeekTable(Module, (ushort)start, before); // what the module holds, all of it acknowledged
            sim.CutPowerAfterFramBytes(Module, 100); // the next parameter write (gear_ratio, 4 bytes) has its FRAM record torn 100 bytes in
        });
        using (var client = new BusClient(link, clock))
        {
            using var output = new StringWriter();
            var failed = Assert.Throws<IOException>(() => new Commissioner(Setup(sim, unit, path), client, output).Run());
            Assert.True(link.Injected);
            log.WriteLine(failed.Message);
            torn = System.Text.RegularExpressions.Regex.Match(failed.Message, @"writing (\w+)\[(\d)\] = (-?\d+) failed \(Timeout");
            Assert.True(torn.Success, failed.Message);
            Assert.StartsWith("commissioning right upper arm: ", failed.Message, StringComparison.Ordinal);
            Assert.EndsWith("the module is not recorded: fix it and run commission again", failed.Message, StringComparison.Ordinal);
            Assert.DoesNotContain('\n', failed.Message);
            Assert.Equal(ReplyOutcome.Timeout, client.Ping(Module, out _).Outcome); // the cut tripped: no power
        }

        Assert.Null(UnitFile.Load(path)!.Module(Module));

        // Power back: the module restarts from its FRAM with the ID and parameters of every acknowledged write, the torn
        // one lost whole (nothing half-written, and not the defaults a corrupt record would give).
        sim.PowerCycle(Module);
        var after = new byte[end - start];
        sim.PeekTable(Module, (ushort)start, after);
        Assert.Equal(before, after);
        var field = Table[torn!.Groups[1].Value];
        var lost = field.Decode(after.AsSpan(field.At(int.Parse(torn.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture)) - start, field.Size));
        Assert.NotEqual(long.Parse(torn.Groups[3].Value, System.Globalization.CultureInfo.InvariantCulture), lost); // the torn write changed a value, and it is not there
        Assert.Equal(Module, after[Table["id"].At(0) - start]); // numbered before the cut: parameters were being written
        Assert.Equal(Module, sim.BusId(Module));
        using var again = new BusClient(sim.OpenLink(), clock);
        var reader = new ParameterWriter(again, Table);
        Assert.False(((HardwareErrors)reader.Read(Module, "hardware_error_status", 0)).HasFlag(HardwareErrors.ParametersLost));

        using var second = new StringWriter();
        Assert.Equal(0, new Commissioner(Setup(sim, UnitFile.Load(path)!, path), again, second).Run());
        Assert.Contains("module 1 of 6 (right upper arm, id 2): answers at its ID already (a commissioning stopped halfway): writing its parameters again", second.ToString(), StringComparison.Ordinal);
        var recorded = UnitFile.Load(path)!.Module(Module)!;
        var expected = ModuleParameters.For(sim.Definition, sim.Definition.Modules.Modules.Single(m => m.Id == Module), Table).Where(p => p.Field.Name != "baud_rate").ToList();
        Assert.Equal(expected.Count, recorded.Parameters.Count);
        Assert.All(expected, p =>
        {
            Assert.Equal(p.Value, recorded.Parameters[UnitFile.Key(p.Field, p.Motor)]);
            Assert.Equal(p.Value, reader.Read(Module, p.Field.Name, p.Motor));
        });
    }

    private static CommissionSetup Setup(VirtualRobot sim, UnitFile unit, string path) =>
        new(sim.Definition, unit, path, TextReader.Null, Poll: true, new CommissionClock(TimeProvider.System), (_, _) => false);
}
