using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Tests.Support;

using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Client;

/// <summary><see cref="BusClient.FullStateRead"/> on the virtual LB-1.0 (real firmware): fast and fallback paths.</summary>
public sealed class FullStateReadTests
{
    private static readonly ushort Feedback = ControlTable.Firmware["present_position"].At(0);

    [Fact]
    public void Fast_bulk_read_and_sync_reads_return_the_same_feedback()
    {
        using var lb = new VirtualLb();
        var client = lb.Robot.Client;
        var ids = lb.Robot.Controllers.Select(c => c.Id).ToArray();
        var lengths = lb.Robot.Controllers.Select(c => c.ChannelSpan * 8).ToArray();
        Assert.All(lb.Robot.Controllers, c => Assert.Equal(ControlTable.Firmware["firmware_version"].Default, c.FirmwareVersion));
        Assert.All(lb.Robot.Controllers, c => Assert.True(c.FirmwareVersion >= BusClient.FastReadFirmwareVersion));

        lb.Robot.Stop();
        var fast = new byte[lengths.Sum()];
        var slow = new byte[lengths.Sum()];
        var replies = new Reply[ids.Length];
        var retriesBefore = ids.Sum(id => client.Statistics(id).Retries);
        Assert.Equal(ids.Length, client.FullStateRead(Feedback, ids, lengths, fast, replies, fast: true));
        Assert.All(replies, r => Assert.True(r.Succeeded, r.ToString()));
        Assert.Equal(retriesBefore, ids.Sum(id => client.Statistics(id).Retries)); // every part came in the one packet
        Assert.Equal(ids.Length, client.FullStateRead(Feedback, ids, lengths, slow, replies, fast: false));
        Assert.All(replies, r => Assert.True(r.Succeeded, r.ToString()));

        // Positions agree (currents and PWM move between the two reads).
        var offset = 0;
        for (var i = 0; i < ids.Length; i++)
        {
            for (var m = 0; m < lengths[i] / 8; m++)
            {
                Assert.Equal(BitConverter.ToInt32(fast, offset + (8 * m)), BitConverter.ToInt32(slow, offset + (8 * m)));
            }

            offset += lengths[i];
        }
    }

    [Fact]
    public void A_module_missing_from_the_bus_is_timed_out_and_the_ones_after_it_are_asked_again()
    {
        using var lb = new VirtualLb();
        var client = lb.Robot.Client;
        var present = lb.Robot.Controllers.Select(c => c.Id).ToArray();
        byte[] ids = [present[0], 200, present[1]];
        int[] lengths = [8, 8, 8];
        var data = new byte[24];
        var replies = new Reply[3];
        Assert.Equal(2, client.FullStateRead(Feedback, ids, lengths, data, replies, fast: true));
        Assert.True(replies[0].Succeeded);
        Assert.Equal(ReplyOutcome.Timeout, replies[1].Outcome);
        Assert.True(replies[2].Succeeded);
        Assert.True(client.Statistics(present[1]).Retries > 0);
    }

    [Fact]
    public void A_refused_part_keeps_its_place_and_carries_its_error()
    {
        using var lb = new VirtualLb();
        var client = lb.Robot.Client;
        var id = lb.Robot.Controllers[0].Id;
        var data = new byte[2];
        var replies = new Reply[1];
        Assert.Equal(1, client.FullStateRead(3, [id], [2], data, replies, fast: true)); // bytes 3..4 are unmapped
        Assert.Equal(ReplyOutcome.Ok, replies[0].Outcome);
        Assert.Equal(StatusError.Access, StatusErrors.Number(replies[0].Error));
    }

    [Fact]
    public void Buffers_that_do_not_fit_the_lengths_are_refused_with_one_clear_message()
    {
        using var lb = new VirtualLb();
        var ex = Assert.Throws<ArgumentException>(() => lb.Robot.Client.FullStateRead(Feedback, [1, 2], [8], new byte[16], new Reply[2], fast: true));
        Assert.Contains("one length per module", ex.Message, StringComparison.Ordinal);
    }
}
