using System.Diagnostics;
using RobotControl.Host.Recording;
using RobotControl.TestSupport.Mcap;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary><c>robotctl console --record</c>: the console's session is recorded from its start to its stop, and the file is finished after the motors are off.</summary>
public sealed class ConsoleRecordingTests
{
    [Fact]
    public async Task A_recorded_console_session_is_read_by_the_official_reader_with_the_counts_the_recorder_wrote()
    {
        var file = Path.Combine(Directory.CreateTempSubdirectory("rc-console-rec-").FullName, "console.mcap");
        SessionEnd end;
        using (var session = new LiveSession(new LiveSessionOptions { GraphPath = Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"), Catalog = ConsoleFixture.Catalog(), Virtual = true, Record = new RecordingOptions { Path = file } }))
        {
            var waited = Stopwatch.StartNew();
            while (session.Status.Ticks < 500)
            {
                Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), "the session ticks");
                await Task.Delay(20);
            }

            end = session.Close();
        }

        var written = end.Events.Select(e => e.Message).Single(m => m.StartsWith("recording: ", StringComparison.Ordinal));
        var check = McapCheck.Read(file);
        Assert.Null(check.Error);
        Assert.True(check.Complete);
        Assert.Equal(check.StreamCounts, check.IndexedCounts);
        var joints = check.IndexedCounts["/arms/right/joints"];
        Assert.True(joints >= 500, $"{joints} joint messages");
        Assert.Contains($"{check.IndexedCounts.Values.Sum()} messages", written, StringComparison.Ordinal);
        Assert.True(check.IndexedCounts["/safety/run_level"] >= 2, "homing and motors on are on the run-level channel");
    }
}
