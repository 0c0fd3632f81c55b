using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;

using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Client;

/// <summary>REG WRITE, ACTION and the broadcast-ping span of <see cref="BusClient"/>, on the virtual LB-1.0 (real firmware).</summary>
public sealed class MaintenanceTests
{
    private static readonly ControlTableField Watchdog = ControlTable.Firmware["bus_watchdog"];

    [Fact]
    public void Registered_writes_wait_for_the_broadcast_action_and_then_apply_in_every_module()
    {
        using var lb = new VirtualLb(start: false);
        var client = lb.Robot.Client;
        byte[] ids = [1, 2, 11];
        foreach (var id in ids)
        {
            Assert.True(client.RegWrite(id, Watchdog.At(0), [0xF4, 0x01]).Succeeded); // 500 ms
        }

        Assert.All(ids, id => Assert.Equal(0, Read(client, id)));
        client.ActionAll();
        Assert.All(ids, id => Assert.Equal(500, Read(client, id)));
        Assert.Equal(0, Read(client, 3)); // nothing was registered there
    }

    [Fact]
    public void A_refused_registration_is_not_kept_and_an_action_without_one_is_an_instruction_error()
    {
        using var lb = new VirtualLb(start: false);
        var client = lb.Robot.Client;

        var refused = client.RegWrite(1, Watchdog.At(0), [0x61, 0xEA]); // 60001 > 60000
        var action = client.Action(1);

        Assert.Equal(StatusError.DataRange, StatusErrors.Number(refused.Error));
        Assert.Equal(StatusError.Instruction, StatusErrors.Number(action.Error)); // the e-Manual: ACTION without REG WRITE
        Assert.Equal(0, Read(client, 1));
    }

    [Fact]
    public void A_unicast_action_applies_the_registered_write_and_forgets_it()
    {
        using var lb = new VirtualLb(start: false);
        var client = lb.Robot.Client;

        Assert.True(client.RegWrite(2, Watchdog.At(0), [0x64, 0x00]).Succeeded); // 100 ms
        Assert.True(client.Action(2).Succeeded);
        Assert.Equal(100, Read(client, 2));
        Assert.Equal(StatusError.Instruction, StatusErrors.Number(client.Action(2).Error));
    }

    [Theory]
    [InlineData(9_600, 4.217)] // 253 IDs x 16 bytes x 10 bits / 9600 + 0.51 ms of return delay
    [InlineData(1_000_000, 0.04099)]
    public void A_complete_broadcast_ping_lasts_every_ids_slot_plus_the_longest_return_delay(int baud, double seconds) =>
        Assert.Equal(seconds, BusClient.BroadcastPingSpan(baud).TotalSeconds, 3);

    private static long Read(BusClient client, byte id)
    {
        var bytes = new byte[Watchdog.Size];
        Assert.True(client.Read(id, Watchdog.At(0), bytes).Succeeded);
        return Watchdog.Decode(bytes);
    }
}
