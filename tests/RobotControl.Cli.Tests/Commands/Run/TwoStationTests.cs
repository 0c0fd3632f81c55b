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
        using var robot = RobotStation(nats, sim, "10s", robotReport);
        robot.WaitFor("t=", RunProcess.Patience); // its loop runs
        using (var surgeon = SurgeonStation(nats, "6s", false, "--report", surgeonReport))
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
    public void An_e_stop_typed_at_the_surgeons_station_is_acknowledged_by_the_robot_station_which_goes_to_e_stop_from_the_link()
    {
        using var nats = NatsServer.Start();
        using var sim = new SimulatorProcess(RunProcess.Patience);
        var robotReport = Path.Combine(Directory.CreateTempSubdirectory("rc2st").FullName, "robot.json");
        string[] link = ["--link", nats.Url, "--station", "lb1"];
        using var robot = RobotStation(nats, sim, "8s", robotReport, link);
        robot.WaitFor("t=", RunProcess.Patience);
        Assert.Contains($"link: robot station 'lb1' takes the surgeon's E-STOP on rc.lb1.command at {nats.Url}", robot.Output, StringComparison.Ordinal);
        using (var surgeon = SurgeonStation(nats, "4s", true, link))
        {
            surgeon.WaitFor("t=", RunProcess.Patience);
            surgeon.Type("estop");
            surgeon.WaitFor("E-STOP acknowledged by robot station 'lb1'", RunProcess.Patience);
            surgeon.WaitFor("robot station 'lb1': E_STOP", RunProcess.Patience); // its run level, published back
            Assert.True(surgeon.WaitForExit(RunProcess.Patience) is 0 or 1, surgeon.Output);
            Assert.DoesNotContain("NOT ACKNOWLEDGED", surgeon.Output, StringComparison.Ordinal);
        }

        Assert.True(robot.WaitForExit(RunProcess.Patience) is 0 or 1, robot.Output);
        using var r = JsonDocument.Parse(File.ReadAllText(robotReport));
        var safety = r.RootElement.GetProperty("safety");
        Assert.Equal("E_STOP", safety.GetProperty("final_run_level").GetString());

        // The only operator E-STOP of this run is the link's (nobody types at the robot station). It is recorded as a
        // trip whatever the level; it takes the station to E_STOP unless a hard trip of a loaded machine got there first.
        var trip = Assert.Single(safety.GetProperty("trips").EnumerateArray(), t => t.GetProperty("check").GetString() == "operator");
        var stop = safety.GetProperty("run_levels").EnumerateArray().First(t => t.GetProperty("to").GetString() == "E_STOP");
        if (stop.GetProperty("time_s").GetDouble() >= trip.GetProperty("time_s").GetDouble())
        {
            Assert.Equal(("link", "E-STOP from the surgeon's station"), (stop.GetProperty("source").GetString(), stop.GetProperty("reason").GetString()));
        }
        else
        {
            Assert.Equal("supervisor", stop.GetProperty("source").GetString()); // a named trip, before the key (printed: stop)
        }

        Assert.Equal(0, r.RootElement.GetProperty("stop").GetProperty("torque_on").GetArrayLength());
    }

    [Fact]
    public void The_server_killed_mid_run_leaves_the_robot_station_holding_its_arms_and_the_surgeons_station_saying_the_link_is_lost()
    {
        var nats = NatsServer.Start();
        try
        {
            using var sim = new SimulatorProcess(RunProcess.Patience);
            var robotReport = Path.Combine(Directory.CreateTempSubdirectory("rc2st").FullName, "robot.json");
            string[] link = ["--link", nats.Url, "--station", "lb1"];
            using var robot = RobotStation(nats, sim, "60s", robotReport, link); // ended by the test once the link is lost (a slow start may not end its run first)
            robot.WaitFor("t=", RunProcess.Patience);
            using var surgeon = SurgeonStation(nats, "6s", false, link);
            surgeon.WaitFor("robot station 'lb1': PEDAL_DOWN", RunProcess.Patience); // following the surgeon's hands

            nats.Kill();

            surgeon.WaitFor("LINK LOST: no status from robot station 'lb1'", RunProcess.Patience);
            Thread.Sleep(1000); // the robot station runs on without the link a while: its harness presses the pedal again after a hold
            robot.Signal("INT"); // Ctrl+C: motors off, the report written
            Assert.True(robot.WaitForExit(RunProcess.Patience) == 130, robot.Output);
            Assert.True(surgeon.WaitForExit(RunProcess.Patience) is 0 or 1, surgeon.Output);
            using var r = JsonDocument.Parse(File.ReadAllText(robotReport));
            var trips = r.RootElement.GetProperty("safety").GetProperty("trips").EnumerateArray().ToList();

            // Holding, not following, well after the samples stopped: the master timeout holds the arms at the link's age
            // (a hold trip when it was following at the kill) and the pedal cannot take them back to PEDAL_DOWN while the
            // age is over the limit. (A load trip may have held it first; that is a hold too.)
            var safety = r.RootElement.GetProperty("safety");
            Assert.True(safety.GetProperty("final_run_level").GetString() is "PEDAL_UP" or "E_STOP", $"still {safety.GetProperty("final_run_level")} after the link was lost; the robot station said:\n{robot.Output}");
            Assert.DoesNotContain(trips, t => t.GetProperty("check").GetString() == "master_timeout" && t.GetProperty("action").GetString() != "hold");
        }
        finally
        {
            nats.Dispose();
        }
    }

    [Fact]
    public void A_link_without_a_station_name_or_with_a_bad_one_gets_one_line_and_nothing_runs()
    {
        using (var run = new RunProcess("run", SurgeonGraph, "--duration", "1s", "--link", "nats://127.0.0.1:4222"))
        {
            Assert.Equal(2, run.WaitForExit(RunProcess.Patience));
            Assert.Contains("--link needs --station <name>: the robot station's name on the server (e.g. lb1)", run.Output, StringComparison.Ordinal);
        }

        using (var run = new RunProcess("run", SurgeonGraph, "--duration", "1s", "--link", "nats://10.1.2.3:4222", "--station", "lb1"))
        {
            Assert.Equal(2, run.WaitForExit(RunProcess.Patience));
            Assert.Contains("--link 'nats://10.1.2.3:4222': 10.1.2.3 is not the loopback interface and the link is plain text", run.Output, StringComparison.Ordinal);
            Assert.DoesNotContain("ticks", run.Output, StringComparison.Ordinal);
        }
    }

    [Fact]
    public void A_station_without_a_robot_refuses_the_options_that_need_one_in_one_line()
    {
        using var run = new RunProcess("run", SurgeonGraph, "--virtual", "--duration", "1s");
        Assert.Equal(2, run.WaitForExit(RunProcess.Patience));
        Assert.Contains("station-surgeon-lb.json: the graph names no robot file: --virtual runs the virtual robot on a virtual clock; a station without a robot runs on the wall clock (leave --virtual out)", run.Output, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Output, StringComparison.Ordinal);
    }

    /// <summary>The robot station on <paramref name="sim"/>, its links on <paramref name="nats"/> (<c>--continue-on-fault</c>: a loaded machine may starve the simulator process).</summary>
    private static RunProcess RobotStation(NatsServer nats, SimulatorProcess sim, string duration, string report, params string[] more) =>
        new(["run", RobotGraph, "--transport", sim.Transport, "--duration", duration, "--continue-on-fault", "--report", report,
            "--set", $"from_surgeon.url={nats.Url}", "--set", $"to_surgeon.url={nats.Url}", .. more]);

    /// <summary>The surgeon's station, its links on <paramref name="nats"/>; with <paramref name="typing"/>, its standard input is a pipe.</summary>
    private static RunProcess SurgeonStation(NatsServer nats, string duration, bool typing, params string[] more) =>
        new(typing, ["run", SurgeonGraph, "--duration", duration, "--set", $"to_robot.url={nats.Url}", "--set", $"from_robot.url={nats.Url}", .. more]);
}
