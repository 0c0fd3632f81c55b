using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Calibration;
using RobotControl.Robot.Commissioning;
using RobotControl.Simulation;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Commissioning;

/// <summary>
/// <see cref="PotCalibrationRun"/> on the in-process virtual robot (the real firmware, simulated time) with unit
/// variation: a verification sweep over its bound is one line naming the joint and the measured value, the motors
/// end off, the unit file keeps the table as written but not verified, and a rerun redoes that motor.
/// </summary>
public sealed class PotCalibrationRunTests : IDisposable
{
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void A_verification_over_its_bound_fails_naming_the_joint_and_the_value_and_the_motor_is_redone_on_the_next_run()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        var path = Path.Combine(_units, "lb-0201.json");
        var unit = new UnitFile { Unit = "lb-0201", RobotFile = "lb-1.0.json" };
        unit.Modules.Add(new UnitModule { Id = 2, Name = "right upper arm", ModelNumber = 0, FirmwareVersion = 3, Parameters = [] });
        unit.Save(path, lb.Clock.GetUtcNow());
        var strict = new PotCalibrationSetup(lb.Definition, unit, path, TextReader.Null, Yes: true, PotSelection.Parse(lb.Definition, "right.elbow"), Redo: false, new PotCalibrationOptions { VerifyBoundDeg = 0.05 });

        using var first = new StringWriter();
        var failed = Assert.Throws<IOException>(() => new PotCalibrationRun(strict, client, first, CancellationToken.None).Run());

        Assert.Matches(@"^right\.elbow: its pot and its Hall position disagree by up to \d+\.\d\d deg in the verification sweep \(bound 0\.05 deg\): .*run calibrate pots --redo --joints right\.elbow$", failed.Message);
        var recorded = UnitFile.Load(path)!.Module(2)!;
        Assert.False(recorded.PotCalibration!["right.elbow"].Verified);
        Assert.True(recorded.PotCalibration["right.elbow"].WorstDeg > 0.05);
        Assert.Equal(3 + PotCalibrationTable.MaxPoints, recorded.Parameters.Keys.Count(k => k.StartsWith("pot_cal_", StringComparison.Ordinal)));
        var torque = new byte[1];
        Assert.True(client.Read(2, ControlTable.Firmware["torque_enable"].At(0), torque).Succeeded);
        Assert.Equal(0, torque[0]);

        using var second = new StringWriter();
        var again = strict with { Unit = UnitFile.Load(path)!, Options = new PotCalibrationOptions() };
        Assert.Equal(0, new PotCalibrationRun(again, client, second, CancellationToken.None).Run());
        Assert.Contains("right.elbow: verified, pot and Hall position agree within ", second.ToString(), StringComparison.Ordinal);
        Assert.Contains("unit lb-0201: 1 pot calibrated and verified", second.ToString(), StringComparison.Ordinal);
        Assert.True(UnitFile.Load(path)!.Module(2)!.PotCalibration!["right.elbow"].Verified);
    }
}
