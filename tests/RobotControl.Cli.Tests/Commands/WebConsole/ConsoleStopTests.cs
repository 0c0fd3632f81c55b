using System.Text.Json;
using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.WebConsole;

/// <summary>
/// Stopping <c>robotctl console</c> (a child process, as an operator runs it) with Ctrl+C or SIGTERM: the motors go off,
/// every module is read back, the console says what they answered, writes the session's report and exits 0.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed class ConsoleStopTests
{
    [Fact]
    public void Ctrl_C_on_the_virtual_robot_switches_torque_off_reads_it_back_and_writes_the_report()
    {
        var report = Path.Combine(Directory.CreateTempSubdirectory("rcconsole").FullName, "session.json");
        using (var console = new RunProcess("console", RunProcess.Graph, "--virtual", "--bind", "127.0.0.1:0", "--report", report))
        {
            console.WaitFor("Ctrl+C stops", RunProcess.Patience);
            Assert.Matches(@"console: http://127\.0\.0\.1:\d+/\?token=[0-9a-f]{32}\n", console.Output); // the URL to open carries the session's token, on loopback too
            Thread.Sleep(500); // the session runs a while
            console.Signal("INT");
            Assert.Equal(0, console.WaitForExit(RunProcess.Patience));
            Assert.Contains("SIGINT: stopping", console.Output, StringComparison.Ordinal);
            Assert.Contains("stop: torque off on all 6 modules (read back)", console.Output, StringComparison.Ordinal);
            Assert.Contains($"report: {report}", console.Output, StringComparison.Ordinal);
        }

        using var doc = JsonDocument.Parse(File.ReadAllText(report));
        var root = doc.RootElement;
        var status = root.GetProperty("status");
        Assert.Equal("teleop-lb.json", status.GetProperty("graph").GetString());
        Assert.Equal("stopped", status.GetProperty("session").GetString());
        Assert.False(status.GetProperty("torque_on").GetBoolean());
        Assert.True(status.GetProperty("ticks").GetInt64() > 0, status.ToString());
        var stop = root.GetProperty("stop");
        Assert.Equal(6, stop.GetProperty("modules").GetInt32());
        Assert.True(stop.GetProperty("torque_off").GetBoolean(), stop.ToString());
        Assert.Equal(0, stop.GetProperty("latched_errors").GetArrayLength());
        var last = root.GetProperty("events").EnumerateArray().Last();
        Assert.Equal("stopped: torque off on all 6 modules (read back)", last.GetProperty("message").GetString());
        Assert.Contains(root.GetProperty("timings").EnumerateArray(), t => t.GetProperty("component").GetString()!.StartsWith("bus cycle", StringComparison.Ordinal));
    }

    [Fact]
    public void SIGTERM_on_a_pty_bus_with_real_time_threads_leaves_every_module_torque_off_as_read_back_independently()
    {
        using var sim = new SimulatorProcess(RunProcess.Patience);
        var report = Path.Combine(Directory.CreateTempSubdirectory("rcconsole").FullName, "session.json");
        using (var console = new RunProcess("console", RunProcess.Graph, "--transport", sim.Transport, "--bind", "127.0.0.1:0", "--report", report, "--rt-priority", "80"))
        {
            console.WaitFor("Ctrl+C stops", RunProcess.Patience);
            Thread.Sleep(1000); // the wall-clock loop and the bus thread run a while
            console.Signal("TERM");
            Assert.Equal(0, console.WaitForExit(RunProcess.Patience));
            Assert.Contains("SIGTERM: stopping", console.Output, StringComparison.Ordinal);
            Assert.Contains("stop: torque off on all 6 modules (read back)", console.Output, StringComparison.Ordinal);
        }

        using (var doc = JsonDocument.Parse(File.ReadAllText(report)))
        {
            Assert.True(doc.RootElement.GetProperty("stop").GetProperty("torque_off").GetBoolean());
            Assert.StartsWith("serial:", doc.RootElement.GetProperty("status").GetProperty("transport").GetString(), StringComparison.Ordinal);
            var threads = doc.RootElement.GetProperty("events").EnumerateArray().Select(e => e.GetProperty("message").GetString()!).Single(m => m.StartsWith("threads: ", StringComparison.Ordinal));
            Assert.Matches("^threads: (SCHED_FIFO priority 80|no real-time priority: .*); any CPU; CPU wake-up latency (held at 0 us|not held: .*)", threads);
        }

        // A stall of this shared machine can trip a module's bus watchdog mid-session (the module doing its job); the
        // stop is what is tested: every module answers with torque off.
        sim.AssertTorqueOff(latchedAllowed: true);
    }

    [Fact]
    public async Task With_a_page_streaming_Ctrl_C_switches_the_motors_off_and_reads_them_back_before_the_server_closes()
    {
        var report = Path.Combine(Directory.CreateTempSubdirectory("rcconsole").FullName, "session.json");
        using (var console = new RunProcess("console", RunProcess.Graph, "--virtual", "--bind", "127.0.0.1:0", "--report", report))
        {
            console.WaitFor("Ctrl+C stops", RunProcess.Patience);
            var page = new Uri(System.Text.RegularExpressions.Regex.Match(console.Output, @"console: (http://\S+)").Groups[1].Value);
            using var socket = new System.Net.WebSockets.ClientWebSocket();
            var stream = new UriBuilder(page) { Scheme = "ws", Path = "/api/stream" }.Uri;
            await socket.ConnectAsync(stream, CancellationToken.None); // a page streaming, never read: the server's frames queue up
            await Task.Delay(500);
            console.Signal("INT");
            Assert.Equal(0, console.WaitForExit(RunProcess.Patience));
            var output = console.Output;
            Assert.Contains("stop: torque off on all 6 modules (read back)", output, StringComparison.Ordinal);
        }

        using var doc = JsonDocument.Parse(File.ReadAllText(report));
        var stop = doc.RootElement.GetProperty("stop");
        Assert.True(stop.GetProperty("torque_off").GetBoolean(), stop.ToString());

        // Read back before the server is closed: not after its connections' graceful shutdown (30 s with a page open).
        Assert.True(stop.GetProperty("read_back_after_ms").GetDouble() < 5_000, stop.ToString());
    }

    [Fact]
    public void A_cpu_this_machine_does_not_have_is_refused_before_the_session_starts() =>
        Cli.AssertRefused(Cli.Run("console", RunProcess.Graph, "--virtual", "--cpu", "1023"), $"--cpu 1023: this machine has CPUs 0..{Environment.ProcessorCount - 1}");

    [Fact]
    public void A_report_file_in_a_folder_that_does_not_exist_is_refused_before_the_session_starts() =>
        Cli.AssertRefused(Cli.Run("console", RunProcess.Graph, "--virtual", "--report", "/nonexistent-folder/session.json"), "--report");
}
