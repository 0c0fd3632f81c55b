using RobotControl.Bus.Client;
using RobotControl.Bus.Tests.Support;

namespace RobotControl.Bus.Tests.Client;

/// <summary>
/// Reads and writes with a retry budget of their own (<c>retries</c>): asked again past the client's
/// <see cref="BusClientOptions.Retries"/> while no answer comes in time, and no more than the budget.
/// </summary>
public sealed class InsistingTests
{
    private const int Baud = 1_000_000;

    // The first three requests are answered 5 ms late (their timeout is under 1 ms), the fourth in time.
    private static BusClient Client(out LateReplyLink link)
    {
        link = new LateReplyLink(Baud, 5000, 5000, 5000, 50);
        return new BusClient(link, link.Clock, new BusClientOptions { Retries = 1 });
    }

    [Fact]
    public void A_read_with_its_own_budget_gets_through_where_the_client_budget_gives_up()
    {
        using var client = Client(out var link);
        var data = new byte[4];
        Assert.Equal(ReplyOutcome.Timeout, client.Read(1, 10, data).Outcome); // 2 requests: the client's budget
        Assert.Equal(2, link.Requests.Count);

        Assert.Equal(ReplyOutcome.Ok, client.Read(1, 20, data, retries: 3).Outcome); // the 3rd request late, the 4th in time
        Assert.Equal(LateReplyLink.Pattern(20, 4), data);
        Assert.Equal(4, link.Requests.Count);
        Assert.Equal(3, client.Statistics(1).Timeouts);
        Assert.Equal(2, client.Statistics(1).Retries);
    }

    [Fact]
    public void A_write_with_its_own_budget_asks_no_more_than_its_budget()
    {
        using var client = Client(out var link);
        Assert.Equal(ReplyOutcome.Timeout, client.Write(1, 64, [1], retries: 2).Outcome);
        Assert.Equal(3, link.Requests.Count);

        Assert.Equal(ReplyOutcome.Ok, client.Write(1, 64, [1], retries: 0).Outcome); // the 4th request is answered
        Assert.Equal(4, link.Requests.Count);
        Assert.All(link.Requests, r => Assert.Equal(RobotControl.Bus.Protocol.Instruction.Write, r.Instruction));
    }

    [Fact]
    public void A_negative_budget_is_refused()
    {
        using var client = Client(out _);
        Assert.Throws<ArgumentOutOfRangeException>(() => client.Read(1, 10, new byte[4], retries: -1));
        Assert.Throws<ArgumentOutOfRangeException>(() => client.Write(1, 64, [1], retries: -1));
    }
}
