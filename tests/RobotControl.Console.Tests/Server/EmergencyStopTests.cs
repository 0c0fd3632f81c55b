using System.Net;
using System.Net.Http.Json;
using System.Text.Json;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>
/// Stopping is never a privilege and never waits: E-STOP is accepted from a console that only watches, and it
/// overtakes commands queued for the bus thread.
/// </summary>
public sealed class EmergencyStopTests
{
    [Fact]
    public async Task A_watching_console_stops_the_robot()
    {
        using var session = Open();
        await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
        using var operatorClient = ConsoleFixture.Client(server, "operator-a");
        (await operatorClient.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        using var watcher = ConsoleFixture.Client(server, "watcher-b");
        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PostAsJsonAsync("api/pedal", new { down = true })).StatusCode); // an action: operator only

        var response = await watcher.PostAsync("api/estop", null);

        Assert.Equal(HttpStatusCode.OK, response.StatusCode);
        var body = await response.Content.ReadFromJsonAsync<JsonElement>();
        Assert.Contains("run level E_STOP", body.GetProperty("message").GetString(), StringComparison.Ordinal);
        await StatusShows(session, "E_STOP");
        Assert.Contains(session.EventsAfter(0), e => e.Message.Contains("(console): operator's emergency stop on the console", StringComparison.Ordinal));
    }

    [Fact]
    public async Task An_emergency_stop_behind_fifty_slow_queued_commands_completes_first()
    {
        using var session = Open();
        var modules = session.Controllers.Where(c => c.Present).Select(c => c.Id).ToList();
        var queued = Enumerable.Range(0, 50).Select(i => session.ReloadParametersAsync(modules[i % modules.Count])).ToList(); // each: a module's parameter reads

        var stop = await session.EmergencyStopAsync();
        var stillQueued = queued.Count(t => !t.IsCompleted);

        Assert.True(stop.Succeeded, stop.Message);
        Assert.Contains("run level E_STOP", stop.Message, StringComparison.Ordinal);
        Assert.True(stillQueued >= 40, $"only {stillQueued} of 50 queued commands were still waiting when the stop completed");
        var results = await Task.WhenAll(queued);
        var cut = results.Where(r => !r.Succeeded).ToList();
        Assert.True(cut.Count <= 1, string.Join("\n", cut.Select(r => r.Message))); // at most the one running when the stop came
        Assert.All(cut, r => Assert.Contains("cut short before its next bus transaction", r.Message, StringComparison.Ordinal));
    }

    /// <summary>Waits for the status snapshot (published ten times a second) to show <paramref name="level"/>.</summary>
    private static async Task StatusShows(LiveSession session, string level)
    {
        var waited = System.Diagnostics.Stopwatch.StartNew();
        while (session.Status.RobotState != level)
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(5), $"the status still says {session.Status.RobotState}");
            await Task.Delay(20);
        }
    }

    private static LiveSession Open() => new(new LiveSessionOptions
    {
        GraphPath = Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"),
        Catalog = ConsoleFixture.Catalog(),
        Virtual = true,
    });
}
