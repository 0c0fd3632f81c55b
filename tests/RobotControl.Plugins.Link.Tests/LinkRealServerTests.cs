using NATS.Client.Core;
using RobotControl.TestSupport;
using RobotControl.TestSupport.Nats;

namespace RobotControl.Plugins.Link.Tests;

/// <summary>link_out and link_in on one subject of a real nats-server, ticked by hand (one tick per ms of loop time).</summary>
public sealed class LinkRealServerTests
{
    [Fact]
    public void Samples_arrive_with_the_values_sent_in_order_with_their_sequence_numbers()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        using var outPlugin = LinkTestSupport.Out(server.Url, subject);
        using var inPlugin = LinkTestSupport.In(server.Url, subject);
        var sender = new PluginDriver(outPlugin).Start();
        var receiver = new PluginDriver(inPlugin).Start();
        receiver.Tick();
        Assert.Equal(0, receiver["sequence"]);
        Assert.Equal(LinkInPlugin.NoSampleAgeMs, receiver["sample_age_ms"]);
        Assert.Equal(0, receiver["fresh"]);

        // The subscription reaches the server some time after the connection opens: samples sent before are not
        // delivered (and are no gap: the first sample a receiver sees starts its count).
        LinkTestSupport.WaitFor(() => outPlugin.IsConnected && inPlugin.IsConnected, "both ends connected");
        for (var k = 1; inPlugin.Received == 0; k++)
        {
            sender.Set(("x", k), ("y", -k)).Tick();
            Thread.Sleep(5);
        }

        Thread.Sleep(100); // the warm-up samples still on the way arrive
        receiver.Tick();
        var next = (long)receiver["sequence"] + 1;
        for (var k = 0; k < 200; k++, next++)
        {
            var received = inPlugin.Received;
            sender.Set(("x", 1000 + k), ("y", k * 0.5)).Tick();
            Assert.Equal(next, sender["sequence"]);
            LinkTestSupport.WaitFor(() => inPlugin.Received > received, $"sample {next} (sent {outPlugin.Sent}, dropped {outPlugin.Dropped}, received {inPlugin.Received}, errors: {outPlugin.LastError}, {inPlugin.LastError})");
            receiver.Tick();
            Assert.Equal(next, receiver["sequence"]);
            Assert.Equal(1000 + k, receiver["x"]);
            Assert.Equal(k * 0.5, receiver["y"]);
            Assert.InRange(receiver["sample_age_ms"], 0, 10_000); // a transit on one machine, not "no sample yet" (1e9)
            Assert.Equal(1, receiver["connected"]);
        }

        Assert.Equal(0, receiver["gaps"]);
        Assert.Equal(0, receiver["reordered"]);
        Assert.Equal(0, receiver["bad_frames"]);
        Assert.Equal(0, sender["dropped"]);
        Assert.Equal(1, sender["connected"]);
    }

    [Fact]
    public void The_age_is_the_transit_when_a_sample_arrives_and_grows_with_loop_time_until_the_next()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        using var outPlugin = LinkTestSupport.Out(server.Url, subject);
        using var inPlugin = new LinkInPlugin(
            new LinkInSettings { Url = server.Url, Subject = subject, Signals = "x,y", StaleAfterMs = 1000, WhenStale = StaleValues.Zero },
            RobotControl.Plugins.Sdk.PluginContext.Standalone("in"));
        var sender = new PluginDriver(outPlugin).Start();
        var receiver = new PluginDriver(inPlugin).Start();
        LinkTestSupport.WaitFor(() => outPlugin.IsConnected && inPlugin.IsConnected, "both ends connected");
        while (inPlugin.Received == 0)
        {
            sender.Set(("x", 5), ("y", 6)).Tick();
            Thread.Sleep(5);
        }

        Thread.Sleep(50); // the samples still on the way arrive
        receiver.Tick();
        var arrival = receiver["sample_age_ms"];
        receiver.Tick(300);
        var later = receiver["sample_age_ms"];
        receiver.Tick(800);

        // On one machine the transit is the time the sample took (well under a second, never negative); then the age
        // grows by the loop time that passed (1 ms per tick), whatever the wall clock did meanwhile.
        Assert.InRange(arrival, 0, 1000);
        Assert.Equal(arrival + 300, later, 1e-9);
        Assert.Equal(arrival + 1100, receiver["sample_age_ms"], 1e-9);
        Assert.Equal(0, receiver["fresh"]);
        Assert.Equal(0, receiver["x"]); // when_stale: zero
    }

    [Fact]
    public void An_age_carried_by_the_link_comes_out_with_the_links_own_age_added_and_is_never_younger_than_it()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        using var outPlugin = LinkTestSupport.Out(server.Url, subject, "x,touch_age");
        using var inPlugin = new LinkInPlugin(
            new LinkInSettings { Url = server.Url, Subject = subject, Signals = "x,touch_age", Ages = "touch_age", StaleAfterMs = 50, WhenStale = StaleValues.Zero },
            RobotControl.Plugins.Sdk.PluginContext.Standalone("in"));
        var sender = new PluginDriver(outPlugin).Start();
        var receiver = new PluginDriver(inPlugin).Start();
        receiver.Tick();
        Assert.Equal(LinkInPlugin.NoSampleAgeMs, receiver["touch_age"]); // before the first sample: never heard from, not 0

        LinkTestSupport.WaitFor(() => outPlugin.IsConnected && inPlugin.IsConnected, "both ends connected");
        while (inPlugin.Received == 0)
        {
            sender.Set(("x", 5), ("touch_age", 3)).Tick();
            Thread.Sleep(5);
        }

        Thread.Sleep(50); // the samples still on the way arrive
        receiver.Tick();
        Assert.Equal(3 + receiver["sample_age_ms"], receiver["touch_age"], 1e-9);
        Assert.Equal(5, receiver["x"]);

        receiver.Tick(200); // stale: when_stale zeroes the values, but an age keeps growing with the link's
        Assert.Equal(0, receiver["fresh"]);
        Assert.Equal(0, receiver["x"]);
        Assert.Equal(3 + receiver["sample_age_ms"], receiver["touch_age"], 1e-9);
        Assert.True(receiver["touch_age"] > 200, $"touch_age {receiver["touch_age"]} ms");
    }

    [Fact]
    public async Task Gaps_reordering_duplicates_and_malformed_frames_from_another_publisher_are_counted_not_thrown()
    {
        using var server = NatsServer.Start();
        var subject = LinkTestSupport.NewSubject();
        using var inPlugin = LinkTestSupport.In(server.Url, subject, name: "from_surgeon");
        var receiver = new PluginDriver(inPlugin).Start();
        LinkTestSupport.WaitFor(() => inPlugin.IsConnected, "link_in connected");
        await using var publisher = new NatsConnection(NatsOpts.Default with { Url = server.Url });
        var layout = LinkFrame.Layout(["x", "y"]);

        // Until the subscription is in place on the server, sequence 1 is sent again (the first one seen starts the count).
        while (inPlugin.Received == 0)
        {
            await publisher.PublishAsync(subject, Frame(layout, 1, 1.0));
            await Task.Delay(10);
        }

        foreach (var sequence in new long[] { 2, 3, 7, 5, 7, 8 })
        {
            await publisher.PublishAsync(subject, Frame(layout, sequence, sequence));
        }

        await publisher.PublishAsync(subject, new byte[] { 1, 2, 3 });
        await publisher.PublishAsync(subject, Frame(LinkFrame.Layout(["y", "x"]), 9, 9));
        // One publisher's messages arrive in order: when the last frame is in, all are.
        LinkTestSupport.WaitFor(() => inPlugin.LastBadFrame?.Contains("signal names differ", StringComparison.Ordinal) == true, "the last frame");
        receiver.Tick();
        var ones = inPlugin.Received - 8;

        Assert.Equal(8, receiver["sequence"]);
        Assert.Equal(8, receiver["x"]);
        Assert.Equal(3, receiver["gaps"]); // 4, 5 and 6 were missing when 7 came
        Assert.Equal(ones - 1 + 2, receiver["reordered"]); // the repeated 1s, 5 after 7, 7 twice
        Assert.Equal(2, receiver["bad_frames"]);
        Assert.StartsWith($"'from_surgeon': bad frame on {subject}: signal names differ", inPlugin.LastBadFrame, StringComparison.Ordinal);
        Assert.Equal(1, receiver["connected"]);
    }

    [Fact]
    public void Wrong_credentials_leave_the_link_disconnected_with_the_reason()
    {
        using var server = NatsServer.StartWithUser("surgeon", "right");
        var subject = LinkTestSupport.NewSubject();
        using var outPlugin = new LinkOutPlugin(
            new LinkOutSettings { Url = server.Url, Subject = subject, User = "surgeon", Password = "wrong" },
            RobotControl.Plugins.Sdk.PluginContext.Standalone("to_robot"));
        using var inPlugin = new LinkInPlugin(
            new LinkInSettings { Url = server.Url, Subject = subject, User = "surgeon", Password = "right" },
            RobotControl.Plugins.Sdk.PluginContext.Standalone("from_surgeon"));
        var sender = new PluginDriver(outPlugin).Start();
        new PluginDriver(inPlugin).Start();

        LinkTestSupport.WaitFor(() => outPlugin.LastError is not null && inPlugin.IsConnected, "the refusal and the good login");
        sender.Tick(10);

        Assert.Equal(0, sender["connected"]);
        Assert.Equal($"{server.Url}: Maximum authentication attempts exceeded (credentials: user 'surgeon' and a password)", outPlugin.LastError);
        Assert.Equal(0, inPlugin.Received);
    }

    [Fact]
    public void An_unreachable_server_leaves_the_link_disconnected_with_one_line_saying_so()
    {
        using var server = NatsServer.Start();
        var url = server.Url;
        server.Kill(); // a port where nothing listens
        using var inPlugin = LinkTestSupport.In(url, LinkTestSupport.NewSubject(), name: "from_robot");
        var receiver = new PluginDriver(inPlugin).Start();

        LinkTestSupport.WaitFor(() => inPlugin.LastError is not null, "the error");
        receiver.Tick();

        Assert.Equal($"{url}: no server answers (still trying)", inPlugin.LastError);
        Assert.Equal(0, receiver["connected"]);
        Assert.Equal(LinkInPlugin.NoSampleAgeMs, receiver["sample_age_ms"]);
        Assert.Equal(0, receiver["fresh"]);
    }

    private static byte[] Frame(uint layout, long sequence, double x)
    {
        var frame = new byte[LinkFrame.Length(2)];
        LinkFrame.Write(frame, layout, sender: 4242, sequence, loopNs: 0, LinkFrame.UnixNs(DateTimeOffset.UtcNow), [x, -x]);
        return frame;
    }
}
