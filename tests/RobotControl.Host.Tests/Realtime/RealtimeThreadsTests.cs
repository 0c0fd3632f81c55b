using RobotControl.Host.Realtime;

namespace RobotControl.Host.Tests.Realtime;

/// <summary>How the bus and loop threads are scheduled: each applies SCHED_FIFO to itself, at one priority.</summary>
public sealed class RealtimeThreadsTests
{
    [Fact]
    public void Both_threads_get_the_priority_though_dotnet_threads_do_not_inherit_it_and_the_caller_keeps_its_own()
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }

        var callerPolicy = SchedulerCalls.GetScheduler(0);
        var threads = new RealtimeThreads(priority: 20, cpu: null);
        (int Policy, int Priority) bus = default, loop = default;
        var plain = Observe(static () => { }); // a new .NET thread does not inherit the creator's policy
        threads.Start(p => bus = Observe(p), p => loop = Observe(p));
        Assert.Equal(callerPolicy, SchedulerCalls.GetScheduler(0)); // the caller keeps its own
        if (!threads.GotRealtimePriority)
        {
            // Without CAP_SYS_NICE or an rtprio limit the threads run normally, and the outcome says why.
            Assert.Contains("no real-time priority", threads.Outcome, StringComparison.Ordinal);
            return;
        }

        Assert.Equal((0, 0), plain); // SCHED_OTHER
        Assert.Equal((SchedulerCalls.SchedFifo, 20), bus);
        Assert.Equal((SchedulerCalls.SchedFifo, 20), loop);
        Assert.Equal("SCHED_FIFO priority 20; any CPU", threads.Outcome);
    }

    /// <summary>Starts a thread as the bus and the loop do (prologue first) and reads the policy and priority it runs with.</summary>
    private static (int Policy, int Priority) Observe(Action prologue)
    {
        (int, int) seen = default;
        var t = new Thread(() =>
        {
            prologue();
            var p = 0;
            _ = SchedulerCalls.GetParam(0, ref p);
            seen = (SchedulerCalls.GetScheduler(0), p);
        });
        t.Start();
        t.Join();
        return seen;
    }
}
