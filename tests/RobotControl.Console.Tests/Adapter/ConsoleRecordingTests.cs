using System.Diagnostics;
using System.Net;
using System.Net.Http.Json;
using System.Text.Json;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.TestSupport.Mcap;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;
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

    [Fact]
    public async Task Every_operator_command_the_console_answers_is_recorded_with_who_sent_it_and_the_answer()
    {
        var file = Path.Combine(Directory.CreateTempSubdirectory("rc-console-rec-").FullName, "commands.mcap");
        using (var session = new LiveSession(new LiveSessionOptions { GraphPath = Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"), Catalog = ConsoleFixture.Catalog(), Virtual = true, Record = new RecordingOptions { Path = file } }))
        {
            await using (var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null))
            {
                using var surgeon = ConsoleFixture.Client(server, "surgeon");
                using var watcher = ConsoleFixture.Client(server, "watcher");
                Assert.Equal(HttpStatusCode.OK, (await surgeon.PostAsync("api/operator", null)).StatusCode);
                Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PostAsJsonAsync("api/torque", new { on = false })).StatusCode);
                await surgeon.PostAsJsonAsync("api/pedal", new { down = false });
                Assert.Equal(HttpStatusCode.OK, (await watcher.PostAsync("api/estop", null)).StatusCode);
            }

            session.Close();
        }

        using var recording = McapFile.Open(file);
        var commands = recording.Messages([recording.Channel(RecordingTopics.Operator)!.Id])
            .Select(m => JsonDocument.Parse(m.Data).RootElement)
            .Select(e => (Who: e.GetProperty("who").GetString()!, What: e.GetProperty("what").GetString()!))
            .ToList();

        Assert.Equal(4, commands.Count);
        Assert.Equal(("console surgeon (watching) at 127.0.0.1", "POST /api/operator -> 200"), commands[0]);
        Assert.Equal(("console watcher (watching) at 127.0.0.1", "POST /api/torque {\"on\":false} -> 403 another console holds the operator role; this one watches"), commands[1]);
        Assert.Equal("console surgeon (operator) at 127.0.0.1", commands[2].Who);
        Assert.StartsWith("POST /api/pedal {\"down\":false} -> ", commands[2].What, StringComparison.Ordinal);
        Assert.Equal("console watcher (watching) at 127.0.0.1", commands[3].Who);
        Assert.StartsWith("POST /api/estop -> 200 ", commands[3].What, StringComparison.Ordinal);
    }
}
