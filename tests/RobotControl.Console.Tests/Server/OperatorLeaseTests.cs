using System.Net;
using Microsoft.Extensions.Time.Testing;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>The operator role lapses 10 s after its holder's last request: an open page (polling the status) keeps it, a closed one loses it.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class OperatorLeaseTests(ConsoleFixture console)
{
    [Fact]
    public async Task An_open_operator_page_keeps_the_role_and_a_silent_one_loses_it_after_the_lease()
    {
        var time = new FakeTimeProvider();
        await using var server = await ConsoleServer.StartAsync(console.Session, BindAddress.Parse("127.0.0.1:0"), null, time);
        using var holder = ConsoleFixture.Client(server, "lease-holder");
        using var other = ConsoleFixture.Client(server, "lease-other");
        Assert.Equal(HttpStatusCode.OK, (await holder.PostAsync("api/operator", null)).StatusCode);

        for (var i = 0; i < 3; i++)
        {
            time.Advance(TimeSpan.FromSeconds(8)); // 24 s in all, each poll within the lease
            Assert.Equal(HttpStatusCode.OK, (await holder.GetAsync("api/status")).StatusCode);
        }

        Assert.Equal(HttpStatusCode.Conflict, (await other.PostAsync("api/operator", null)).StatusCode);
        time.Advance(OperatorRole.Lease + TimeSpan.FromSeconds(1)); // the holder's page closed
        Assert.Equal(HttpStatusCode.OK, (await other.PostAsync("api/operator", null)).StatusCode);
        Assert.Equal("lease-other", server.Operator.Holder);
    }
}
