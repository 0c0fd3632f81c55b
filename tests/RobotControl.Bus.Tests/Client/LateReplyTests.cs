using RobotControl.Bus.Client;
using RobotControl.Bus.Tests.Support;

namespace RobotControl.Bus.Tests.Client;

/// <summary>
/// Replies delayed past their timeout and delivered afterwards (a scripted bus): none is taken for the answer to
/// another request, each is counted as late, and none is counted as a CRC error. At 1 Mbaud a 4-byte read's timeout
/// is its wire time (14 + 15 bytes, 290 us) plus the 500 us margin: 790 us after it is sent.
/// </summary>
public sealed class LateReplyTests
{
    private const int Baud = 1_000_000;

    private static BusClient Client(LateReplyLink link, int retries = 0) =>
        new(link, link.Clock, new BusClientOptions { Retries = retries });

    private static (Reply Reply, byte[] Data) Read(BusClient client, byte id, ushort address)
    {
        var data = new byte[4];
        return (client.Read(id, address, data), data);
    }

    [Fact]
    public void A_late_reply_waiting_in_the_link_is_drained_before_the_next_request_and_counted()
    {
        using var client = Client(new LateReplyLink(Baud, 2000));
        Assert.Equal(ReplyOutcome.Timeout, Read(client, 1, 10).Reply.Outcome);
        ((LateReplyLink)client.Link).Idle(TimeSpan.FromMilliseconds(3)); // the reply to address 10 arrives now

        var (reply, data) = Read(client, 1, 20); // same module, same length: only the drain tells them apart
        Assert.Equal(ReplyOutcome.Ok, reply.Outcome);
        Assert.Equal(LateReplyLink.Pattern(20, 4), data);
        Assert.Equal(1, client.LateReplies);
        Assert.Equal(1, client.Statistics(1).LateReplies);
        Assert.Equal(0, client.CrcErrors);
    }

    [Fact]
    public void A_reply_a_little_late_is_waited_out_before_the_next_request_to_the_same_module()
    {
        // The read of address 10 is answered at 1,000 us, after its 790 us timeout. The next read, of the same length,
        // would be answered 300 us after it is sent: without the wait the late reply would come inside its window.
        using var client = Client(new LateReplyLink(Baud, 1000, 300));
        Assert.Equal(ReplyOutcome.Timeout, Read(client, 1, 10).Reply.Outcome);

        var (reply, data) = Read(client, 1, 20);
        Assert.Equal(ReplyOutcome.Ok, reply.Outcome);
        Assert.Equal(LateReplyLink.Pattern(20, 4), data);
        Assert.Equal(1, client.LateReplies);
        Assert.Equal(0, client.CrcErrors);
    }

    [Fact]
    public void A_late_reply_of_another_length_inside_a_wait_is_skipped_and_the_right_reply_taken()
    {
        // The late read reply (4 data bytes) arrives while the write waits for its acknowledgement (no data).
        var link = new LateReplyLink(Baud, 1300, 600);
        using var client = Client(link);
        Assert.Equal(ReplyOutcome.Timeout, Read(client, 1, 10).Reply.Outcome);

        var ack = client.Write(1, 40, [1]);
        Assert.Equal(ReplyOutcome.Ok, ack.Outcome);
        Assert.Equal(1, client.LateReplies);
        Assert.Equal(1, client.Statistics(1).LateReplies);
        Assert.Equal(1, client.Statistics(1).Timeouts);
    }

    [Fact]
    public void A_late_reply_from_another_module_inside_a_wait_is_skipped_and_counted_for_that_module()
    {
        var link = new LateReplyLink(Baud, 1300, 600);
        using var client = Client(link);
        Assert.Equal(ReplyOutcome.Timeout, Read(client, 2, 10).Reply.Outcome);

        var (reply, data) = Read(client, 1, 10);
        Assert.Equal(ReplyOutcome.Ok, reply.Outcome);
        Assert.Equal(LateReplyLink.Pattern(10, 4), data);
        Assert.Equal(1, client.Statistics(2).LateReplies);
        Assert.Equal(0, client.Statistics(1).LateReplies);
    }

    [Fact]
    public void After_a_retry_the_first_attempts_reply_is_counted_late_not_taken_by_the_next_read()
    {
        // Attempt 1 is answered at 2,000 us (too late), the retry promptly; then the next read goes out.
        var link = new LateReplyLink(Baud, 2000, 50, 50, 50);
        using var client = Client(link, retries: 2);
        var first = Read(client, 1, 10);
        Assert.Equal(ReplyOutcome.Ok, first.Reply.Outcome);
        Assert.Equal(LateReplyLink.Pattern(10, 4), first.Data);
        Assert.Equal(1, client.Statistics(1).Retries);

        var second = Read(client, 1, 20);
        link.Idle(TimeSpan.FromMilliseconds(3));
        var third = Read(client, 1, 30);
        Assert.Equal(LateReplyLink.Pattern(20, 4), second.Data);
        Assert.Equal(LateReplyLink.Pattern(30, 4), third.Data);
        Assert.Equal(1, client.LateReplies);
        Assert.Equal(0, client.CrcErrors);
    }
}
