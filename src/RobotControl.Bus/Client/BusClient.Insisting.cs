using System.Buffers.Binary;
using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Client;

/// <summary>Transactions with a retry budget of their own, for the few that must get through.</summary>
public sealed partial class BusClient
{
    /// <summary>
    /// As <see cref="Read(byte, ushort, Span{byte})"/>, asking again up to <paramref name="retries"/> times (instead of
    /// <see cref="BusClientOptions.Retries"/>) when no good reply comes: for the few transactions that must get
    /// through a noisy or late bus, such as arming and a stop's read-back. A module's error status is final.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="retries"/> is negative.</exception>
    public Reply Read(byte id, ushort address, Span<byte> data, int retries)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(retries);
        Span<byte> p = stackalloc byte[4];
        BinaryPrimitives.WriteUInt16LittleEndian(p, address);
        BinaryPrimitives.WriteUInt16LittleEndian(p[2..], (ushort)data.Length);
        var reply = Transact(id, Instruction.Read, p, data.Length, retries);
        if (reply.Outcome == ReplyOutcome.Ok && _decoder.Parameters.Length == data.Length)
        {
            _decoder.Parameters.CopyTo(data);
        }
        else if (reply.Outcome == ReplyOutcome.Ok)
        {
            data.Clear(); // a refusal without data (firmware before issue 29; with it, the length asked of zeros)
        }

        return reply;
    }

    /// <summary>
    /// As <see cref="Write(byte, ushort, ReadOnlySpan{byte})"/>, asking again up to <paramref name="retries"/> times
    /// (instead of <see cref="BusClientOptions.Retries"/>) when no good acknowledgement comes; only for idempotent
    /// writes (torque, watchdog). A module's error status (a refusal) is final.
    /// </summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="retries"/> is negative.</exception>
    public Reply Write(byte id, ushort address, ReadOnlySpan<byte> data, int retries)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(retries);
        return WriteAt(Instruction.Write, id, address, data, retries);
    }
}
