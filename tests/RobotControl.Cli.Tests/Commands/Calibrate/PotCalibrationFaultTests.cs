using System.Globalization;
using System.Text.RegularExpressions;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Commissioning;
using RobotControl.Robot.Calibration;
using RobotControl.Simulation;
using RobotControl.TestSupport;
using Xunit.Abstractions;

namespace RobotControl.Cli.Tests.Commands.Calibrate;

/// <summary>
/// Faults in the middle of a pot calibration (<see cref="PotCalibrationRun"/> on the in-process virtual robot: the real
/// firmware, simulated time, unit variation), each injected when the right elbow is 10 degrees into its sweep: a jammed
/// joint, a Hall connector off, a pot that fails while it is measured and one that fails in the verification sweep.
/// Each stops the calibration with the module's motors off (read back over the bus and on the simulator's drive) and one
/// line naming the motor and the measured value; the module's FRAM and the unit file keep nothing half-written.
/// </summary>
public sealed class PotCalibrationFaultTests(ITestOutputHelper log) : IDisposable
{
    private const byte Module = 2; // the right upper arm: the right elbow alone
    private const double Deg = Math.PI / 180;
    private static readonly ControlTable Table = ControlTable.Firmware;
    private static readonly string[] PotCalFields = ["pot_cal_count", "pot_cal_pos0", "pot_cal_step", .. Enumerable.Range(0, PotCalibrationTable.MaxPoints).Select(k => $"pot_cal_raw{k}")];
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void A_joint_jammed_mid_sweep_stops_with_its_motor_off_and_its_lag_in_one_line_nothing_stored_and_a_rerun_once_freed_completes()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var elbow = lb.Sim.Axis(0, "elbow");
        var fixture = elbow.OutputAngleRad;
        var setup = Setup(lb, "lb-0301");
        var held = PotTable(lb);

        var failed = RunWithFault(lb, setup, () => elbow.ObstacleTorqueNm = 5); // far beyond what the elbow drive can push

        var line = Regex.Match(failed.Message, @"^right\.elbow: (\d+\.\d) deg behind its setpoint for 0\.5 s \(limit 5 deg\): blocked, .*motors off; free the joint, put the arm in its fixture pose and run the calibration again$");
        Assert.True(line.Success, failed.Message);
        Assert.True(double.Parse(line.Groups[1].Value, CultureInfo.InvariantCulture) > 5, failed.Message);
        AssertMotorOff(lb, elbow);
        AssertNothingRecorded(setup.UnitPath);

        // The operator frees the joint and puts the arm back in its fixture pose (the module off meanwhile: it restarts
        // from its FRAM, which still holds the table it had).
        elbow.ObstacleTorqueNm = 0;
        lb.Sim.TurnWhileOff(elbow, fixture);
        Assert.Equal(held, PotTable(lb));

        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        using var output = new StringWriter();
        Assert.Equal(0, new PotCalibrationRun(setup with { Unit = UnitFile.Load(setup.UnitPath)! }, client, output, CancellationToken.None).Run());
        Assert.Contains("right.elbow: verified, pot and Hall position agree within ", output.ToString(), StringComparison.Ordinal);
        Assert.True(UnitFile.Load(setup.UnitPath)!.Module(Module)!.PotCalibration!["right.elbow"].Verified);
        Assert.NotEqual(held, PotTable(lb));
    }

    [Fact]
    public void A_Hall_connector_off_mid_sweep_latches_the_modules_Hall_error_and_stops_with_the_motor_off_naming_it()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var elbow = lb.Sim.Axis(0, "elbow");
        var setup = Setup(lb, "lb-0302");
        var held = PotTable(lb);

        var failed = RunWithFault(lb, setup, () => elbow.HallFailedCode = 7); // the connector off: the pull-ups read 111

        Assert.Matches(@"^module 2 \(right upper arm\): latched hall during the sweep \(right\.elbow: hall, \d+ invalid or skipped Hall states?\): motors off; find the cause \(a Hall wire or sensor", failed.Message);
        AssertMotorOff(lb, elbow);
        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        Assert.True(new ParameterWriter(client, Table).Read(Module, "hall_error_count", 0) > 0);
        AssertNothingRecorded(setup.UnitPath);
        lb.Sim.PowerCycle(Module);
        Assert.Equal(held, PotTable(lb));
    }

    [Fact]
    public void A_pot_that_fails_while_it_is_measured_is_refused_by_the_fit_naming_the_motor_and_the_readings_and_nothing_is_stored()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var elbow = lb.Sim.Axis(0, "elbow");
        var setup = Setup(lb, "lb-0303");
        var held = PotTable(lb);

        var failed = RunWithFault(lb, setup, () => elbow.PotFailedRaw = 0); // an open wiper pulled to ground

        Assert.Matches(@"^right\.elbow: (calibration point \d fits a pot reading of -?\d+, outside the ADC's 0\.\.4095|the pot readings fitted at points \d and \d \(-?\d+, -?\d+\) are not strictly monotonic).*; its module keeps the table it had: run calibrate pots again$", failed.Message);
        AssertMotorOff(lb, elbow);
        AssertNothingRecorded(setup.UnitPath);
        lb.Sim.PowerCycle(Module);
        Assert.Equal(held, PotTable(lb));
    }

    [Fact]
    public void A_pot_that_fails_in_the_verification_sweep_is_refused_naming_the_motor_and_the_disagreement_with_the_table_stored_whole_and_not_verified()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var elbow = lb.Sim.Axis(0, "elbow");
        var setup = Setup(lb, "lb-0304");
        var output = new StringWriter();

        var failed = RunWithFault(lb, setup, () => elbow.PotFailedRaw = 0, output, () => output.ToString().Contains("written into its FRAM and read back", StringComparison.Ordinal));

        var line = Regex.Match(failed.Message, @"^right\.elbow: its pot and its Hall position disagree by up to (\d+\.\d\d) deg in the verification sweep \(bound 1\.5 deg\): .*run calibrate pots --redo --joints right\.elbow$");
        Assert.True(line.Success, failed.Message);
        var worst = double.Parse(line.Groups[1].Value, CultureInfo.InvariantCulture);
        Assert.True(worst > 10, failed.Message); // a pot at 0 reads as the far end of the table
        AssertMotorOff(lb, elbow);
        var recorded = UnitFile.Load(setup.UnitPath)!.Module(Module)!;
        Assert.False(recorded.PotCalibration!["right.elbow"].Verified);
        Assert.Equal(Math.Round(worst, 2), Math.Round(recorded.PotCalibration["right.elbow"].WorstDeg!.Value, 2));

        // Stored whole: the module's FRAM (read after a power cycle) holds exactly the table the unit file records.
        lb.Sim.PowerCycle(Module);
        Assert.Equal(PotCalFields.Select(f => recorded.Parameters[$"{f}[0]"]).ToArray(), PotTable(lb));
    }

    private PotCalibrationSetup Setup(VirtualLb lb, string name)
    {
        var path = Path.Combine(_units, name + ".json");
        var unit = new UnitFile { Unit = name, RobotFile = "lb-1.0.json" };
        unit.Modules.Add(new UnitModule { Id = Module, Name = "right upper arm", ModelNumber = 0, FirmwareVersion = 3, Parameters = [] });
        unit.Save(path, lb.Clock.GetUtcNow());
        return new PotCalibrationSetup(lb.Definition, unit, path, TextReader.Null, Yes: true, PotSelection.Parse(lb.Definition, "right.elbow"), Redo: false, new PotCalibrationOptions());
    }

    /// <summary>Runs the calibration, <paramref name="fault"/> injected once the elbow is 10 degrees from where it started (and <paramref name="also"/> holds); the line it fails with.</summary>
    private IOException RunWithFault(VirtualLb lb, PotCalibrationSetup setup, Action fault, StringWriter? output = null, Func<bool>? also = null)
    {
        var elbow = lb.Sim.Axis(0, "elbow");
        var start = elbow.OutputAngleRad;
        var link = new FaultOnCue(lb.Sim.OpenLink(), () => Math.Abs(elbow.OutputAngleRad - start) > 10 * Deg && (also?.Invoke() ?? true), fault);
        using var client = new BusClient(link, lb.Clock);
        output ??= new StringWriter();
        var failed = Assert.Throws<IOException>(() => new PotCalibrationRun(setup, client, output, CancellationToken.None).Run());
        Assert.True(link.Injected, "the fault was never injected: " + output);
        log.WriteLine(failed.Message);
        Assert.DoesNotContain('\n', failed.Message);
        return failed;
    }

    /// <summary>The module's torque reads back off over the bus, and the simulator's drive is disabled with no PWM.</summary>
    private static void AssertMotorOff(VirtualLb lb, VirtualAxis axis)
    {
        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        var torque = new byte[1];
        Assert.True(client.Read(Module, Table["torque_enable"].At(0), torque).Succeeded);
        Assert.Equal(0, torque[0]);
        Assert.False(axis.DriverEnabled, $"{axis.Config.FullName}: the simulator's drive is still enabled");
        Assert.Equal(0, axis.Pwm);
    }

    /// <summary>The unit file records no calibration and no pot table for the module.</summary>
    private static void AssertNothingRecorded(string path)
    {
        var recorded = UnitFile.Load(path)!.Module(Module)!;
        Assert.True(recorded.PotCalibration is null or { Count: 0 }, "a calibration was recorded");
        Assert.DoesNotContain(recorded.Parameters.Keys, k => k.StartsWith("pot_cal_", StringComparison.Ordinal));
    }

    /// <summary>The elbow's pot table as its module holds it.</summary>
    private static long[] PotTable(VirtualLb lb)
    {
        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        var reader = new ParameterWriter(client, Table);
        return [.. PotCalFields.Select(f => reader.Read(Module, f, 0))];
    }
}
