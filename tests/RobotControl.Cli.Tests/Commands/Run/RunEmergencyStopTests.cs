using System.Text.Json;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>
/// The command line's E-STOP during <c>robotctl run</c> (a child process, as a user runs it): the operator types it, the
/// safety supervisor trips <c>operator</c> with source <c>cli</c>, the arms hold at E_STOP for the rest of the run, and
/// the report names the trip.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class RunEmergencyStopTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(120);

    [Fact]
    public void Typing_estop_during_a_run_trips_the_supervisor_and_the_arms_hold_for_the_rest_of_the_run()
    {
        var report = Path.Combine(Directory.CreateTempSubdirectory("rcestop").FullName, "report.json");
        using (var run = new RunProcess(typing: true, "run", RunProcess.Graph, "--virtual", "--duration", "60s", "--report", report))
        {
            run.WaitFor("t=", Patience);
            Assert.Contains("E-STOP: type e and Enter", run.Output, StringComparison.Ordinal);
            run.Type("nothing"); // other lines are ignored
            run.Type("estop");
            Assert.Equal(1, run.WaitForExit(Patience)); // a trip: exit 1
            Assert.Contains("E-STOP (command line)", run.Output, StringComparison.Ordinal);
        }

        using var doc = JsonDocument.Parse(File.ReadAllText(report));
        var safety = doc.RootElement.GetProperty("safety");
        Assert.Equal("E_STOP", safety.GetProperty("final_run_level").GetString());
        var trip = Assert.Single(safety.GetProperty("trips").EnumerateArray());
        Assert.Equal("operator", trip.GetProperty("check").GetString());
        Assert.Equal("hold", trip.GetProperty("action").GetString());
        var last = safety.GetProperty("run_levels").EnumerateArray().Last();
        Assert.Equal(("PEDAL_DOWN", "E_STOP", "cli"), (last.GetProperty("from").GetString(), last.GetProperty("to").GetString(), last.GetProperty("source").GetString()));
        Assert.Equal(60000, doc.RootElement.GetProperty("ticks").GetInt64()); // a hold trip: the run went on, holding
        Assert.True(trip.GetProperty("time_s").GetDouble() < 59, "the E-STOP came only at the end of the run");
    }

    [Theory]
    [InlineData("estop", true)]
    [InlineData(" E ", true)]
    [InlineData("e-stop", true)]
    [InlineData("stop", false)]
    [InlineData("", false)]
    public void Only_an_estop_line_asks_for_an_emergency_stop(string line, bool stop) =>
        Assert.Equal(stop, RobotControl.Cli.Commands.Run.OperatorKeys.IsEmergencyStop(line));
}
