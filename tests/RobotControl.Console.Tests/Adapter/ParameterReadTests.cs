using System.Diagnostics;
using RobotControl.Host.Harness;
using RobotControl.WebConsole.Adapter;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary>
/// A module that does not answer its parameter reads (silent from the start) does not end the session: the reads are
/// tried again on later turns and then left unknown, each said in the event log, and the session keeps running.
/// </summary>
public sealed class ParameterReadTests
{
    [Fact]
    public async Task A_module_silent_from_the_start_leaves_its_parameters_unknown_and_the_session_running()
    {
        using var session = ConsoleFixture.VirtualSession(FaultInjection.Parse("silent=left.forearm@0s"));
        var waited = Stopwatch.StartNew();
        while (!session.EventsAfter(0).Any(e => e.Message.Contains("parameters stay unknown", StringComparison.Ordinal)))
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), string.Join("\n", session.EventsAfter(0).Select(e => e.Message)));
            Assert.NotEqual("failed", session.Status.Session);
            await Task.Delay(50);
        }

        var messages = session.EventsAfter(0).Select(e => e.Message).ToList();
        Assert.Contains(messages, m => m.EndsWith("reading module 13's parameters again later (try 1 of 5)", StringComparison.Ordinal));
        Assert.Contains(messages, m => m.EndsWith("module 13's parameters stay unknown after 5 tries (reload them from the bus page)", StringComparison.Ordinal));
        Assert.DoesNotContain(messages, m => m.StartsWith("the session thread stopped", StringComparison.Ordinal));
        Assert.NotEqual("failed", session.Status.Session);
        var stop = session.Close().Stop!;
        Assert.Empty(stop.TorqueOn); // every module that answers has its motors off
        Assert.Equal(["13 \"left forearm\""], stop.Unreachable); // the silent one cannot answer the read-back
    }

    [Fact]
    public async Task Ten_reloads_at_once_are_read_one_parameter_per_gap_and_the_loop_sharing_the_bus_thread_keeps_its_time()
    {
        using var session = ConsoleFixture.VirtualSession();
        var waited = Stopwatch.StartNew();
        while (session.Status.Session != "running" && waited.Elapsed < TimeSpan.FromSeconds(60))
        {
            await Task.Delay(20);
        }

        Assert.True((await session.PedalAsync(true)).Succeeded); // teleoperation drives the arms: the loop is timed at 10 ms
        var reloads = await Task.WhenAll(Enumerable.Range(0, 10).Select(_ => session.ReloadParametersAsync(1)));

        Assert.All(reloads, r => Assert.True(r.Succeeded, r.Message));
        var messages = session.EventsAfter(0).Select(e => e.Message).ToList();
        Assert.DoesNotContain(messages, m => m.Contains("deadline_miss", StringComparison.Ordinal) || m.Contains("host_stall", StringComparison.Ordinal));
        Assert.Contains(messages, m => m.Contains("PEDAL_DOWN", StringComparison.Ordinal));
        Assert.DoesNotContain(messages, m => m.Contains("-> PEDAL_UP", StringComparison.Ordinal) && m.Contains("loop", StringComparison.Ordinal));
    }
}
