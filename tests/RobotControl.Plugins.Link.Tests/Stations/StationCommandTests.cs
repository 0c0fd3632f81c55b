using NATS.Client.Core;
using RobotControl.Plugins.Link.Stations;
using RobotControl.TestSupport.Nats;

namespace RobotControl.Plugins.Link.Tests.Stations;

/// <summary>The surgeon station's commands to a robot station, over a real nats-server.</summary>
public sealed class StationCommandTests
{
    [Fact]
    public async Task An_e_stop_is_answered_with_the_stations_line_and_a_repeat_of_it_gets_the_same_answer_but_is_acted_on_once()
    {
        using var server = NatsServer.Start();
        var address = StationAddress.Parse(server.Url, "lb1");
        var acted = new List<string>();
        await using var responder = RobotStationEndpoint.Start(address, word =>
        {
            lock (acted)
            {
                acted.Add(word);
            }

            return "taken";
        });
        await using var sender = SurgeonStationEndpoint.Open(address);

        var outcome = await sender.SendAsync(StationCommands.EmergencyStop);
        Assert.True(outcome.Answered, outcome.Line);
        Assert.Matches("^estop [0-9a-f]{32}: taken$", outcome.Line);

        // The same command again (a repeat whose first answer came late or was lost): the same answer, not acted on twice.
        // (The sender itself repeats after 100 ms without an answer, so on a loaded machine this may be its third send.)
        await using var raw = new NatsConnection(new NatsOpts { Url = server.Url });
        var id = outcome.Line.Split(':')[0];
        var again = await raw.RequestAsync<string, string>(address.CommandSubject, id, replyOpts: new NatsSubOpts { Timeout = TimeSpan.FromSeconds(5) });
        Assert.Equal(outcome.Line, again.Data);
        var junk = await raw.RequestAsync<string, string>(address.CommandSubject, "reboot now", replyOpts: new NatsSubOpts { Timeout = TimeSpan.FromSeconds(5) });
        Assert.Equal("refused: 'reboot now' is not a command (estop <id>)", junk.Data);
        Assert.Equal([StationCommands.EmergencyStop], acted);
        Assert.Equal(1, responder.Acted);
    }

    [Theory]
    [InlineData("nats://127.0.0.1:4222", "", "--station '': give the robot station's name (letters, digits, _ and -), e.g. lb1")]
    [InlineData("nats://127.0.0.1:4222", "lb.1", "--station 'lb.1': give the robot station's name (letters, digits, _ and -), e.g. lb1")]
    [InlineData("nats://192.168.1.20:4222", "lb1", "--link 'nats://192.168.1.20:4222': 192.168.1.20 is not the loopback interface and the link is plain text (samples and credentials unencrypted); add --link-plaintext-remote to use it anyway")]
    public void A_bad_address_gets_one_line_naming_the_option(string url, string station, string expected)
    {
        Assert.Equal(expected, Assert.Throws<FormatException>(() => StationAddress.Parse(url, station)).Message);
    }
}
