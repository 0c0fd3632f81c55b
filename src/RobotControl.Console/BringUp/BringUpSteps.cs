using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Calibration;
using RobotControl.Robot.Commissioning;

namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// The two bring-up steps as the console runs them, each the CLI command's own run (<see cref="Commissioner"/>,
/// <see cref="PotCalibrationRun"/>) on a bus opened for the step: the operator's Enter is the page's Continue and a
/// stop is the step's cancellation.
/// </summary>
internal static class BringUpSteps
{
    /// <summary><c>robotctl commission</c>: waits for each module (<paramref name="poll"/>) or for Continue after the operator connected it.</summary>
    public static void Commission(BringUpSetup setup, bool poll, TextWriter output, OperatorPrompt prompt, CancellationToken stop)
    {
        var record = UnitFile.Load(setup.UnitPath) ?? new UnitFile { Unit = setup.Unit, RobotFile = setup.RobotFile };
        var factoryBaud = ModuleParameters.BaudFromCode((int)ControlTable.Firmware["baud_rate"].Default);
        using var client = setup.Open(factoryBaud);
        var commission = new CommissionSetup(setup.Robot, record, setup.UnitPath, prompt, poll, new CommissionClock(setup.Time), (baud, id) =>
        {
            using var other = setup.Open(baud);
            return other.Ping(id, out _).Outcome == ReplyOutcome.Ok;
        });
        _ = new Commissioner(commission, client, output, stop).Run();
    }

    /// <summary><c>robotctl calibrate pots</c> of <paramref name="joints"/> (null: every motor): the fixture pose confirmed with Continue.</summary>
    public static void Calibrate(BringUpSetup setup, string? joints, bool redo, TextWriter output, OperatorPrompt prompt, CancellationToken stop)
    {
        var record = UnitFile.Load(setup.UnitPath) ?? throw new IOException($"unit {setup.Unit}: no unit file {setup.UnitPath}; commission the unit first (Commission)");
        var selection = PotSelection.Parse(setup.Robot, joints);
        using var client = setup.Open(setup.Robot.Modules.BaudRate);
        var calibration = new PotCalibrationSetup(setup.Robot, record, setup.UnitPath, prompt, Yes: false, selection, redo, new PotCalibrationOptions());
        _ = new PotCalibrationRun(calibration, client, output, stop).Run();
    }
}
