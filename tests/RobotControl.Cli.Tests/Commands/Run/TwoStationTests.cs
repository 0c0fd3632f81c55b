using System.Text.Json;
using RobotControl.TestSupport.Nats;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>
/// <c>graphs/teleop-lb.json</c> cut in two at its wires (docs/link.md): the surgeon's station (Touch, homing, scaling,
/// clutch, walls, damping) and the robot's (IK and the robot, on <c>bus-sim --pty</c>), each a <c>robotctl run</c> of
/// its own, linked through a real <c>nats-server</c>.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class TwoStationTests
{
    private static string SurgeonGraph => RunProcess.RepoFile("graphs", "station-surgeon-lb.json");

    private static string RobotGraph => RunProcess.RepoFile("graphs", "station-robot-lb.json");

    [Fact]
    public void Two_stations_through_a_real_nats_server_drive_the_robot_from_the_surgeons_hands_and_each_writes_its_report()
    {
        using var nats = NatsServer.Start();
        using var sim = new SimulatorProcess(RunProcess.Patience);
        var folder = Directory.CreateTempSubdirectory("rc2st").FullName;
        var robotReport = Path.Combine(folder, "robot.json");
        var surgeonReport = Path.Combine(folder, "surgeon.json");

        // The robot station first: until the surgeon's samples come it holds its arms (master_timeout, never heard from).
        using var robot = new RunProcess("run", RobotGraph, "--transport", sim.Transport, "--duration", "10s", "--continue-on-fault", "--report", robotReport,
            "--set", $"from_surgeon.url={nats.Url}", "--set", $"to_surgeon.url={nats.Url}");
        robot.WaitFor("t=", RunProcess.Patience); // its loop runs
        using (var surgeon = new RunProcess("run", SurgeonGraph, "--duration", "6s", "--report", surgeonReport,
            "--set", $"to_robot.url={nats.Url}", "--set", $"from_robot.url={nats.Url}"))
        {
            var code = surgeon.WaitForExit(RunProcess.Patience);
            Assert.True(code is 0 or 1, surgeon.Output); // 1: deadline misses on a loaded machine; 2 would be a refusal
            Assert.Contains("a station without a robot", surgeon.Output, StringComparison.Ordinal);
        }

        var robotCode = robot.WaitForExit(RunProcess.Patience);
        Assert.True(robotCode is 0 or 1, robot.Output);

        using var s = JsonDocument.Parse(File.ReadAllText(surgeonReport));
        var station = s.RootElement;
        Assert.Equal("station", station.GetProperty("kind").GetString());
        Assert.True(station.GetProperty("ticks").GetInt64() > 1000, station.ToString());
        Assert.Equal(0, station.GetProperty("plugin_faults").GetArrayLength());
        var signals = station.GetProperty("signals");
        Assert.True(signals.GetProperty("to_robot.sequence").GetDouble() > 1000, signals.ToString()); // a sample a tick went out
        Assert.True(signals.GetProperty("from_robot.sequence").GetDouble() > 1000, signals.ToString()); // and the robot's forces and state came back
        Assert.Equal(0, signals.GetProperty("from_robot.bad_frames").GetDouble());

        // The robot followed the surgeon's hands for seconds: PEDAL_DOWN lasts only while the samples are fresh (the
        // master timeout holds the arms within 50 ms of the last one), and without the link it never did for long.
        using var r = JsonDocument.Parse(File.ReadAllText(robotReport));
        var run = r.RootElement;
        Assert.True(run.GetProperty("safety").GetProperty("pedal_down_s").GetDouble() > 0.5, run.GetProperty("safety").ToString());
        Assert.True(run.GetProperty("tracking_error_mm").GetProperty("rms").GetDouble() > 0, run.ToString());
        Assert.Equal(6, run.GetProperty("stop").GetProperty("modules").GetInt32());
        Assert.Equal(0, run.GetProperty("stop").GetProperty("torque_on").GetArrayLength());
        sim.AssertTorqueOff(latchedAllowed: true);
    }

    [Fact]
    public void A_station_without_a_robot_refuses_the_options_that_need_one_in_one_line()
    {
        using var run = new RunProcess("run", SurgeonGraph, "--virtual", "--duration", "1s");
        Assert.Equal(2, run.WaitForExit(RunProcess.Patience));
        Assert.Contains("station-surgeon-lb.json: the graph names no robot file: --virtual runs the virtual robot on a virtual clock; a station without a robot runs on the wall clock (leave --virtual out)", run.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Output, StringComparison.Ordinal);
    }
}
