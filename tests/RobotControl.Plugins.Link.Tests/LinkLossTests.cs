using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;
using RobotControl.TestSupport;
using RobotControl.TestSupport.Nats;

namespace RobotControl.Plugins.Link.Tests;

/// <summary>The link in a running loop when its server dies and comes back, and what a tick costs.</summary>
public sealed class LinkLossTests
{
    [Fact]
    public void Server_killed_mid_run_shows_as_lost_and_ageing_while_the_loop_ticks_on_and_the_link_resumes_after_a_restart()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        var json = $$"""
            {
              "schema": "robotcontrol/graph/1",
              "instances": [
                { "name": "to_robot", "type": "link_out", "settings": { "url": "{{server.Url}}", "subject": "{{subject}}", "signals": "x" } },
                { "name": "from_surgeon", "type": "link_in", "settings": { "url": "{{server.Url}}", "subject": "{{subject}}", "signals": "x", "stale_after_ms": 50 } }
              ],
              "wires": []
            }
            """;
        var catalog = PluginCatalog.FromAssemblies(typeof(LinkOutPlugin).Assembly);
        var loaded = GraphFile.LoadFromText(json, RepositoryPaths.Of("graphs/link-test.json"), catalog, TimeProvider.System);
        var sender = loaded.Program.Order.OfType<LinkOutPlugin>().Single();
        var receiver = loaded.Program.Order.OfType<LinkInPlugin>().Single();
        using var loop = new ControlLoop(loaded.Program, TimeProvider.System, 1000);
        loop.Start();
        LinkTestSupport.WaitFor(() => receiver.GetOutput("fresh") == 1 && receiver.GetOutput("sequence") > 0, "samples flowing");

        server.Kill();
        var killedAt = loop.TickCount;
        LinkTestSupport.WaitFor(() => receiver.GetOutput("connected") == 0 && sender.GetOutput("connected") == 0, "both ends to see the loss");
        LinkTestSupport.WaitFor(() => receiver.GetOutput("sample_age_ms") > 1000, "the sample age to pass a second");
        var ticksWhileDown = loop.TickCount - killedAt;
        var freshWhileDown = receiver.GetOutput("fresh");
        var sequenceAtLoss = receiver.GetOutput("sequence");

        server.Restart();
        LinkTestSupport.WaitFor(
            () => receiver.GetOutput("connected") == 1 && receiver.GetOutput("fresh") == 1 && receiver.GetOutput("sequence") > sequenceAtLoss + 100,
            "the link to resume");
        loop.Stop();
        var (sequence, sent, dropped) = ((long)sender.GetOutput("sequence"), sender.Sent, sender.Dropped);

        // The loop never waited for the link: its ticks went on through the outage (the age, loop time since the last
        // sample arrived plus its transit, passed a second; a loaded machine skips the slots of overrun ticks). Every
        // sample is accounted for: sent, dropped (queue overflow, no server) or still queued.
        Assert.True(ticksWhileDown > 300, $"{ticksWhileDown} ticks while the server was down");
        Assert.InRange(sequence - sent - dropped, 0, sender.Settings.Queue);
        Assert.Equal(0, freshWhileDown);
        Assert.True(receiver.GetOutput("gaps") > 0, "no gap after the outage");
        Assert.Equal(0, receiver.GetOutput("reordered"));
        Assert.Equal(0, loaded.Program.FaultCount);
    }

    [Fact]
    public void A_tick_of_either_end_allocates_nothing_while_samples_flow()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        using var sender = LinkTestSupport.Out(server.Url, subject);
        using var receiver = LinkTestSupport.In(server.Url, subject);
        sender.Start(Ticks.At(0));
        receiver.Start(Ticks.At(0));
        LinkTestSupport.WaitFor(() => sender.IsConnected && receiver.IsConnected, "both ends connected");
        var tick = 0L;
        for (; receiver.Received < 100; tick++)
        {
            TickBoth(sender, receiver, tick);
            Thread.Sleep(1);
        }

        var sequenceBefore = receiver.GetOutput("sequence");
        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var end = tick + 2000; tick < end; tick++)
        {
            TickBoth(sender, receiver, tick);
            if (tick % 100 == 0)
            {
                Thread.Sleep(1); // lets the sender and subscriber threads run on a busy machine
            }
        }

        var allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.Equal(0, allocated);
        Assert.True(receiver.GetOutput("sequence") > sequenceBefore, "no sample arrived during the measured ticks");
    }

    private static void TickBoth(LinkOutPlugin sender, LinkInPlugin receiver, long tick)
    {
        sender.SetInput(0, tick);
        sender.SetInput(1, -tick);
        sender.Tick(Ticks.At(tick));
        receiver.Tick(Ticks.At(tick));
    }
}
