using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;

using RobotControl.TestSupport;

namespace RobotControl.Bus.Tests.Client;

/// <summary>
/// A refused read on the virtual LB-1.0 (real firmware): the module answers with the error and the requested length
/// of zero bytes, as ROBOTIS devices do (issue 29: ROBOTIS's SDK's read4ByteTxRx failed on a status without data),
/// and the host takes it as a final refusal with the data cleared, alone or among the replies of a SYNC READ.
/// </summary>
public sealed class RefusedReadTests
{
    [Fact]
    public void A_refused_read_is_a_final_access_error_and_clears_the_data()
    {
        using var lb = new VirtualLb(start: false);
        var client = lb.Robot.Client;
        var data = new byte[] { 0xAA, 0xAA, 0xAA, 0xAA };
        var retries = client.Statistics(1).Retries;

        var reply = client.Read(1, 3, data); // bytes 3..6: 3..5 belong to no field

        Assert.Equal(ReplyOutcome.Ok, reply.Outcome);
        Assert.Equal(StatusError.Access, StatusErrors.Number(reply.Error));
        Assert.False(reply.Succeeded);
        Assert.Equal(new byte[4], data);
        Assert.Equal(retries, client.Statistics(1).Retries); // the module answered: not asked again
    }

    [Fact]
    public void A_refused_part_of_a_sync_read_is_a_final_refusal_and_the_others_are_read()
    {
        using var lb = new VirtualLb(start: false);
        var client = lb.Robot.Client;
        var at = ControlTable.Firmware["motor_count"].At(0);
        byte[] ids = [1, 2];
        var data = new byte[] { 0xAA, 0xAA, 0xAA, 0xAA };
        var replies = new Reply[2];

        client.SyncRead(at, 2, ids, data, replies); // motor_count and byte 3 (no field): refused by every module

        Assert.All(replies, r => Assert.Equal(StatusError.Access, StatusErrors.Number(r.Error)));
        Assert.All(replies, r => Assert.Equal(ReplyOutcome.Ok, r.Outcome));
        Assert.Equal(new byte[4], data);

        client.SyncRead(at, 1, ids, data.AsSpan(0, 2), replies);
        Assert.All(replies, r => Assert.True(r.Succeeded, r.ToString()));
        Assert.All(data[..2], b => Assert.InRange(b, (byte)1, (byte)4)); // each module's motor count
    }
}
