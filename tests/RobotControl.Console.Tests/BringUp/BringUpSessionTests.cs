using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Robot.Calibration;
using RobotControl.Robot.Commissioning;
using RobotControl.Simulation;
using RobotControl.TestSupport;
using RobotControl.WebConsole.BringUp;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Tests.BringUp;

/// <summary>
/// <see cref="BringUpSession"/> on the in-process virtual robot (the real firmware, simulated time) with unit
/// variation: a step waiting for the operator is stopped with its module's motors off (read back) and says so in one
/// line; one step at a time; every refusal one line naming what to do; robot-session commands refused.
/// </summary>
public sealed class BringUpSessionTests : IDisposable
{
    private readonly string _units = Directory.CreateTempSubdirectory("rc-bringup-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public async Task A_calibration_waiting_for_the_fixture_is_stopped_with_its_motors_off_and_no_second_step_starts_meanwhile()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var path = Path.Combine(_units, "lb-0401.json");
        var unit = new UnitFile { Unit = "lb-0401", RobotFile = "lb-1.0.json" };
        unit.Modules.Add(new UnitModule { Id = 2, Name = "right upper arm", ModelNumber = 0, FirmwareVersion = 3, Parameters = [] });
        unit.Save(path, lb.Clock.GetUtcNow());
        using var client = new BusClient(lb.Sim.OpenLink(), lb.Clock);
        Assert.True(client.Write(2, ControlTable.Firmware["torque_enable"].At(0), [1]).Succeeded); // on, as a stopped session may leave it
        using var session = new BringUpSession(Setup(lb, "lb-0401", _ => new BusClient(lb.Sim.OpenLink(), lb.Clock)));

        Assert.True(session.StartCalibration(2, redo: false).Succeeded);
        var job = session.Job!;
        await Until(() => job.State == "waiting");
        Assert.Equal("module 2 (right upper arm): put the arm in its fixture pose (right.elbow 75.0 deg: every joint at mid-range, the jaw half open), keep clear of it, then press Enter", session.Lines.Last);
        var second = session.StartCommission(poll: true);
        Assert.Equal((CommandOutcome.Refused, "commission: calibrate is running; wait for it to end or stop it first"), (second.Outcome, second.Message));
        Assert.True(session.Status.TorqueOn, "a calibration running: the motors may be on");

        var stopped = await session.EmergencyStopAsync();

        Assert.True(stopped.Succeeded, stopped.Message);
        const string Said = "stopped: module 2 (right upper arm)'s motors are off (read back); run calibrate pots again to continue (motors calibrated and verified are kept)";
        Assert.Equal($"E-STOP: {Said}", stopped.Message);
        Assert.Equal(("stopped", Said), (job.State, job.Outcome));
        Assert.Equal(Said, session.Lines.Last);
        Assert.Equal([Said], session.Status.Faults);
        Assert.False(session.Status.TorqueOn);
        var torque = new byte[1];
        Assert.True(client.Read(2, ControlTable.Firmware["torque_enable"].At(0), torque).Succeeded);
        Assert.Equal(0, torque[0]);
        Assert.Null(UnitFile.Load(path)!.Module(2)!.PotCalibration);
    }

    [Fact]
    public async Task A_module_that_goes_silent_mid_calibration_is_named_and_its_motors_are_not_shown_off()
    {
        using var lb = new VirtualLb(new VirtualRobotOptions { UnitVariationSeed = 3 }, start: false);
        var unit = new UnitFile { Unit = "lb-0403", RobotFile = "lb-1.0.json" };
        unit.Modules.Add(new UnitModule { Id = 2, Name = "right upper arm", ModelNumber = 0, FirmwareVersion = 3, Parameters = [] });
        unit.Save(Path.Combine(_units, "lb-0403.json"), lb.Clock.GetUtcNow());
        using var session = new BringUpSession(Setup(lb, "lb-0403", _ => new BusClient(lb.Sim.OpenLink(), lb.Clock)));
        Assert.True(session.StartCalibration(2, redo: false).Succeeded);
        await Until(() => session.Job!.State == "waiting");

        lb.Sim.Disconnect(2); // its cable comes out while the operator sets the fixture
        Assert.True(session.Continue().Succeeded);
        await session.Job!.Ended;

        Assert.Equal("failed", session.Job.State);
        Assert.StartsWith("module 2 (right upper arm): ", session.Job.Outcome, StringComparison.Ordinal);
        Assert.EndsWith($"{PotCalibrator.NotConfirmedOff} (write Timeout, read back Timeout): switch its power off", session.Job.Outcome, StringComparison.Ordinal);
        Assert.True(session.Status.TorqueOn, "motors not confirmed off are not shown off");
        Assert.Equal([session.Job.Outcome!], session.Status.Faults);
    }

    [Fact]
    public async Task Every_refusal_is_one_line_naming_what_to_do_and_robot_commands_are_refused()
    {
        using var lb = new VirtualLb(start: false);
        var opened = 0;
        using var session = new BringUpSession(Setup(lb, "lb-0402", _ =>
        {
            opened++;
            return new BusClient(lb.Sim.OpenLink(), lb.Clock);
        }));

        var none = await session.StopAsync("STOP");
        Assert.Equal((CommandOutcome.Ok, "STOP: no bring-up step is running; this console drives no motor"), (none.Outcome, none.Message));
        var unknown = session.StartCalibration(99, redo: false);
        Assert.Equal(CommandOutcome.NotFound, unknown.Outcome);
        Assert.StartsWith("calibrate: the robot file has no module 99 (modules: 1 right shoulder, 2 right upper arm", unknown.Message, StringComparison.Ordinal);
        var waiting = session.Continue();
        Assert.Equal((CommandOutcome.Refused, "continue: no step is waiting for the operator"), (waiting.Outcome, waiting.Message));
        var torque = await session.TorqueAsync(true);
        Assert.Equal(CommandOutcome.Refused, torque.Outcome);
        Assert.StartsWith("bring-up console: no robot session runs", torque.Message, StringComparison.Ordinal);

        Assert.True(session.StartCalibration(null, redo: false).Succeeded);
        await session.Job!.Ended;
        var path = Path.Combine(_units, "lb-0402.json");
        Assert.Equal(("failed", $"unit lb-0402: no unit file {path}; commission the unit first (Commission)"), (session.Job.State, session.Job.Outcome));
        Assert.Equal(0, opened); // refused before the bus was opened
        Assert.Equal(["== Calibrate pots of unit lb-0402, every module", session.Job.Outcome], session.Lines.After(0).Select(l => l.Text));
        Assert.Equal([2], session.Lines.After(1).Select(l => l.Sequence));
    }

    private BringUpSetup Setup(VirtualLb lb, string unit, Func<int, BusClient> open) =>
        new("lb-1.0.json", lb.Definition, unit, Path.Combine(_units, unit + ".json"), "serial:/dev/pts/test", open, lb.Clock);

    /// <summary>Waits for the step's thread to reach <paramref name="condition"/> (it runs on a thread of its own).</summary>
    private static async Task Until(Func<bool> condition)
    {
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (!condition())
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), "the step did not get there");
            await Task.Delay(10);
        }
    }
}
