using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Client;

/// <summary><see cref="BusClient.Totals"/>: the per-module counters, summed.</summary>
public sealed class BusTotalsTests
{
    [Fact]
    public void Totals_sum_the_counters_of_the_modules_asked_for()
    {
        using var lb = new VirtualLb();
        lb.Robot.Stop();
        var client = lb.Robot.Client;
        var present = lb.Robot.Controllers.Select(c => c.Id).ToArray();
        byte[] ids = [present[0], 200, present[1]];
        client.FullStateRead(ControlTable.Firmware["present_position"].At(0), ids, [8, 8, 8], new byte[24], new Reply[3], fast: true);

        var totals = client.Totals(ids);
        Assert.Equal(ids.Sum(id => client.Statistics(id).FramesSent + client.Statistics(id).FramesReceived), totals.Frames);
        Assert.Equal(ids.Sum(id => client.Statistics(id).Timeouts), totals.Timeouts);
        Assert.Equal(ids.Sum(id => client.Statistics(id).Retries), totals.Retries);
        Assert.True(totals.Timeouts > 0); // ID 200 is not on the bus
        Assert.True(client.Totals([present[0]]).Frames < totals.Frames);
        Assert.Equal(default, client.Totals([]));
    }
}
