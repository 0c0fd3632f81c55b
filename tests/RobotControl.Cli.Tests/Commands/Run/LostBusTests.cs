using System.Text.Json;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>
/// A lost bus is a fault and the report is always written: <c>robotctl run</c> on a pty whose other end (the
/// simulator's process) is killed outright, as an unplugged adapter would end the link.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class LostBusTests
{
    [Fact]
    public void Killing_the_process_behind_the_pty_trips_names_the_modules_says_the_stop_could_not_be_read_back_and_writes_the_report()
    {
        var report = Path.Combine(Directory.CreateTempSubdirectory("rclostbus").FullName, "report.json");
        using var sim = new SimulatorProcess(RunProcess.Patience);
        using (var run = new RunProcess("run", RunProcess.Graph, "--transport", sim.Transport, "--duration", "120s", "--report", report))
        {
            run.WaitFor("  t=", RunProcess.Patience); // the first progress line: teleoperation runs
            sim.Kill();
            Assert.Equal(1, run.WaitForExit(RunProcess.Patience));
            Assert.Contains("the device hung up", run.Output, StringComparison.Ordinal);
            Assert.Matches(@"ROBOT FAULT: safety trip module_silent \w+\.\w+ switched the motors off", run.Output);
            Assert.Contains("stop: torque NOT confirmed off", run.Output, StringComparison.Ordinal);
            Assert.Contains($"report: {report}", run.Output, StringComparison.Ordinal);
        }

        using var doc = JsonDocument.Parse(File.ReadAllText(report));
        var root = doc.RootElement;
        Assert.False(root.GetProperty("interrupted").GetBoolean());
        Assert.StartsWith("safety trip module_silent", root.GetProperty("stopped_on_fault").GetString(), StringComparison.Ordinal);
        var stop = root.GetProperty("stop");
        Assert.False(stop.GetProperty("torque_off").GetBoolean());
        Assert.Equal(6, stop.GetProperty("unreachable").GetArrayLength()); // attempted, and every module named
        Assert.Contains("hung up", stop.GetProperty("link_failure").GetString(), StringComparison.Ordinal);
        var trips = root.GetProperty("safety").GetProperty("trips").EnumerateArray().ToList();
        Assert.Contains(trips, t => t.GetProperty("check").GetString() == "module_silent" && t.GetProperty("action").GetString() == "torque_off");
    }
}
