using RobotControl.TestSupport;

namespace RobotControl.Plugins.Link.Tests;

/// <summary>link_in's bookkeeping of the frames it is given (fed directly, no server).</summary>
public sealed class LinkReceiverTests
{
    private static readonly uint Layout = LinkFrame.Layout(["x", "y"]);

    [Fact]
    public void A_restarted_sender_starts_its_sequence_again_without_counting_reordering()
    {
        using var plugin = LinkTestSupport.In("nats://127.0.0.1:4222", "rc.test.unit");
        var receiver = new PluginDriver(plugin);
        foreach (var sequence in new long[] { 1, 2, 3 })
        {
            plugin.Receiver.Accept(Frame(sender: 11, sequence, x: sequence));
        }

        receiver.Tick();
        Assert.Equal(3, receiver["sequence"]);
        plugin.Receiver.Accept(Frame(sender: 12, sequence: 1, x: 100));
        receiver.Tick();

        Assert.Equal(1, receiver["sequence"]);
        Assert.Equal(100, receiver["x"]);
        Assert.Equal(0, receiver["reordered"]);
        Assert.Equal(0, receiver["gaps"]);
        Assert.Equal(2, plugin.Senders);
    }

    [Fact]
    public void A_bad_frame_changes_nothing_shown_and_the_tick_goes_on()
    {
        using var plugin = LinkTestSupport.In("nats://127.0.0.1:4222", "rc.test.unit", name: "from_robot");
        var receiver = new PluginDriver(plugin);
        plugin.Receiver.Accept(Frame(sender: 5, sequence: 4, x: 7));
        plugin.Receiver.Accept(new byte[LinkFrame.Length(3)]);
        receiver.Tick();

        Assert.Equal(4, receiver["sequence"]);
        Assert.Equal(7, receiver["x"]);
        Assert.Equal(1, receiver["bad_frames"]);
        Assert.Equal("'from_robot': bad frame on rc.test.unit: format version 0, this end reads version 1", plugin.LastBadFrame);
    }

    private static byte[] Frame(uint sender, long sequence, double x)
    {
        var frame = new byte[LinkFrame.Length(2)];
        LinkFrame.Write(frame, Layout, sender, sequence, loopNs: 0, wallNs: 0, [x, -x]);
        return frame;
    }
}
