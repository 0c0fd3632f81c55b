using System.Diagnostics;
using System.Net;
using System.Net.Http.Headers;
using System.Net.Http.Json;
using System.Text.Json;
using System.Text.RegularExpressions;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.WebConsole;

/// <summary>
/// A bus that fails under a console session takes the robot's one path, as in <c>robotctl run</c>: a bus error in the
/// event log, the bus degraded, every module's reply missed, and the supervisor's safe state, all on the status page.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed partial class ConsoleBusErrorTests
{
    [Fact]
    public async Task A_pty_that_hangs_up_under_a_console_is_a_bus_error_a_degraded_bus_and_an_e_stop_on_the_status_page()
    {
        var sim = new SimulatorProcess(RunProcess.Patience);
        using var console = new RunProcess("console", RunProcess.Graph, "--transport", sim.Transport, "--bind", "127.0.0.1:0");
        var output = console.WaitFor("Ctrl+C stops", RunProcess.Patience);
        var url = Url().Match(output);
        using var http = new HttpClient { BaseAddress = new Uri(url.Groups[1].Value) };
        Assert.Equal(HttpStatusCode.Unauthorized, (await http.GetAsync("api/status")).StatusCode); // the printed URL carries the session's token; nothing works without it
        http.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Bearer", url.Groups[2].Value);
        http.DefaultRequestHeaders.Add("X-Console-Client", "bus-error-test");
        (await http.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        var on = await http.PostAsJsonAsync("api/torque", new { on = true }); // on a real bus the session starts at INIT, motors off
        Assert.True(on.IsSuccessStatusCode, await on.Content.ReadAsStringAsync());
        sim.Dispose(); // the simulator ends: the pty hangs up under the console's bus thread

        var waited = Stopwatch.StartNew();
        JsonElement status;
        while (true)
        {
            status = (await http.GetFromJsonAsync<JsonElement>("api/status")).GetProperty("status");
            var faults = status.GetProperty("faults").EnumerateArray().Select(f => f.GetString()!).ToList();
            if (faults.Contains("BusDegraded") && status.GetProperty("robotState").GetString() == "E_STOP")
            {
                Assert.Contains(faults, f => f.StartsWith("trip: module_silent", StringComparison.Ordinal));
                break;
            }

            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(20), $"after the hang-up: {status}");
            await Task.Delay(100);
        }

        var events = await http.GetFromJsonAsync<JsonElement>("api/events?after=0");
        Assert.Contains(events.EnumerateArray(), e => e.GetProperty("message").GetString()!.Contains("bus error: ", StringComparison.Ordinal) && e.GetProperty("message").GetString()!.Contains("hung up", StringComparison.Ordinal));
        console.Signal("TERM");
        Assert.NotEqual(0, console.WaitForExit(RunProcess.Patience)); // nothing answers the stop's read-back: torque is not confirmed off
        Assert.True(console.Output.Contains("torque NOT confirmed off", StringComparison.Ordinal), console.Output);
    }

    [GeneratedRegex(@"console: (http://127\.0\.0\.1:\d+/)\?token=([0-9a-f]{32})")]
    private static partial Regex Url();
}
