using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Simulation.Tests.Support;
using RobotControl.Bus.Transports;

using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests.EndToEnd;

/// <summary>A baud change over the pty: the modules switch after their reply, the simulated line follows the client's port.</summary>
public sealed class BaudChangeTests
{
    [Fact]
    public void After_the_modules_change_baud_a_client_reopening_at_the_new_baud_reaches_them_and_can_change_back()
    {
        using var served = new ServedPty();
        var ids = VirtualLb.Lb.Modules.Modules.Select(m => m.Id).ToArray();
        var options = new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50), Retries = 1 };
        SetBaud(served.SlavePath, served.Sim.BaudRate, ids, 4, options); // code 4 = 2 Mbaud
        using (var old = new BusClient(LinkFactory.Open($"serial:{served.SlavePath}?baud={served.Sim.BaudRate}"), TimeProvider.System, options))
        {
            Assert.Equal(ReplyOutcome.Timeout, old.Ping(ids[0], out _).Outcome); // the modules no longer listen at 1 Mbaud
        }

        using (var fast = new BusClient(LinkFactory.Open($"serial:{served.SlavePath}?baud=2000000"), TimeProvider.System, options))
        {
            Assert.All(ids, id => Assert.True(fast.Ping(id, out _).Succeeded, $"id {id} at 2 Mbaud"));
        }

        Assert.Equal(2_000_000, served.Sim.LineBaud);
        SetBaud(served.SlavePath, 2_000_000, ids, 3, options); // and back to 1 Mbaud
        using var back = new BusClient(LinkFactory.Open($"serial:{served.SlavePath}?baud=1000000"), TimeProvider.System, options);
        Assert.All(ids, id => Assert.True(back.Ping(id, out _).Succeeded, $"id {id} back at 1 Mbaud"));
    }

    private static void SetBaud(string device, int baud, byte[] ids, byte code, BusClientOptions options)
    {
        using var client = new BusClient(LinkFactory.Open($"serial:{device}?baud={baud}"), TimeProvider.System, options);
        foreach (var id in ids)
        {
            Assert.True(client.Write(id, ControlTable.Firmware["baud_rate"].At(0), [code]).Succeeded, $"baud code {code} to id {id}");
        }
    }
}
