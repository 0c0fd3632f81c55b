using System.Buffers.Binary;
using RobotControl.Bus.Protocol;

namespace RobotControl.Bus.Client;

/// <summary>The full-state read of every module per cycle: one FAST BULK READ, or sync reads for older firmware.</summary>
public sealed partial class BusClient
{
    /// <summary>Firmware version from which modules answer FAST SYNC READ / FAST BULK READ (and chain their replies).</summary>
    public const byte FastReadFirmwareVersion = 2;

    /// <summary>FF FF FD 00, ID 0xFE, LEN (2), 0x55: the head of a fast-read status packet.</summary>
    private const int FastHead = 8;

    private readonly byte[] _fast = new byte[FrameConstants.MaxFrameSize];

    /// <summary>
    /// Reads <paramref name="lengths"/>[i] bytes at <paramref name="address"/> of every module <paramref name="ids"/>[i]
    /// into <paramref name="data"/> (back to back, each module its own length). With <paramref name="fast"/> (every
    /// module's firmware at least <see cref="FastReadFirmwareVersion"/>) it is one FAST BULK READ answered by one
    /// combined status packet; otherwise one SYNC READ per run of modules with the same length. A module whose part is
    /// missing or corrupted is asked again on its own. <paramref name="replies"/> receives each module's outcome.
    /// Returns how many modules answered. Allocates nothing.
    /// </summary>
    public int FullStateRead(ushort address, ReadOnlySpan<byte> ids, ReadOnlySpan<int> lengths, Span<byte> data, Span<Reply> replies, bool fast)
    {
        var total = 0;
        foreach (var n in lengths)
        {
            total += n;
        }

        if (lengths.Length != ids.Length || data.Length < total || replies.Length < ids.Length)
        {
            throw new ArgumentException("full-state read: one length per module, and data/replies buffers large enough for them");
        }

        return fast ? FastBulkRead(address, ids, lengths, data, replies) : SyncReadRuns(address, ids, lengths, data, replies);
    }

    private int SyncReadRuns(ushort address, ReadOnlySpan<byte> ids, ReadOnlySpan<int> lengths, Span<byte> data, Span<Reply> replies)
    {
        var answered = 0;
        var offset = 0;
        for (var i = 0; i < ids.Length;)
        {
            var j = i;
            while (j < ids.Length && lengths[j] == lengths[i])
            {
                j++;
            }

            var bytes = (j - i) * lengths[i];
            answered += SyncRead(address, lengths[i], ids[i..j], data.Slice(offset, bytes), replies[i..j]);
            offset += bytes;
            i = j;
        }

        return answered;
    }

    private int FastBulkRead(ushort address, ReadOnlySpan<byte> ids, ReadOnlySpan<int> lengths, Span<byte> data, Span<Reply> replies)
    {
        var p = _params.AsSpan(0, 5 * ids.Length);
        var packet = FastHead;
        for (var i = 0; i < ids.Length; i++)
        {
            p[5 * i] = ids[i];
            BinaryPrimitives.WriteUInt16LittleEndian(p[((5 * i) + 1)..], address);
            BinaryPrimitives.WriteUInt16LittleEndian(p[((5 * i) + 3)..], (ushort)lengths[i]);
            packet += 4 + lengths[i];
            replies[i] = Reply.TimedOut;
            _stats[ids[i]].Sent();
        }

        if (packet > _fast.Length)
        {
            throw new ArgumentException($"full-state read: a {packet}-byte status packet exceeds the {_fast.Length}-byte frame limit");
        }

        var sentAt = Send(FrameConstants.BroadcastId, Instruction.FastBulkRead, p, countStatistics: false);
        var deadline = sentAt + Ticks(WireTime(FrameConstants.Overhead + p.Length + packet)) + (ids.Length * Ticks(_options.ResponseMargin));
        var answered = ReceiveFastPacket(ids, lengths, data, replies, sentAt, deadline, packet - 7);
        if (answered < ids.Length)
        {
            QuietAfterTimeout(); // the rest of the packet may still be on its way
        }

        return answered + AskMissing(address, ids, lengths, data, replies, answered);
    }

    /// <summary>Reads the combined packet and takes each part whose ID and running CRC check out, in list order.</summary>
    private int ReceiveFastPacket(ReadOnlySpan<byte> ids, ReadOnlySpan<int> lengths, Span<byte> data, Span<Reply> replies, long sentAt, long deadline, int expectedLength)
    {
        var have = 0;
        var start = -1;
        var parsed = 0;
        var k = 0;
        var offset = 0;
        ushort crc = 0;
        while (k < ids.Length)
        {
            if (start < 0 && (start = FindFastHead(have)) >= 0)
            {
                if (have - start < FastHead)
                {
                    start = -1; // wait for the rest of the head
                }
                else if (BinaryPrimitives.ReadUInt16LittleEndian(_fast.AsSpan(start + 5)) != expectedLength || _fast[start + 7] != (byte)Instruction.Status)
                {
                    return k;
                }
                else
                {
                    crc = Crc16.Compute(_fast.AsSpan(start, FastHead));
                    parsed = FastHead;
                }
            }

            while (start >= 0 && k < ids.Length && have - start - parsed >= 4 + lengths[k])
            {
                var part = _fast.AsSpan(start + parsed, 4 + lengths[k]);
                crc = Crc16.Compute(part[..^2], crc);
                if (part[1] != ids[k] || crc != BinaryPrimitives.ReadUInt16LittleEndian(part[^2..]))
                {
                    return k; // a corrupted part: the running CRC of every later part fails too
                }

                crc = Crc16.Compute(part[^2..], crc);
                part.Slice(2, lengths[k]).CopyTo(data.Slice(offset, lengths[k]));
                replies[k] = new Reply(ReplyOutcome.Ok, part[0]);
                var stats = _stats[ids[k]];
                stats.Received(_time.GetTimestamp() - sentAt);
                if (part[0] != 0)
                {
                    stats.ErrorReply();
                }

                parsed += part.Length;
                offset += lengths[k];
                k++;
            }

            var remaining = deadline - _time.GetTimestamp();
            if (k == ids.Length || remaining <= 0 || have == _fast.Length)
            {
                break;
            }

            have += _link.Read(_fast.AsSpan(have), TimeSpan.FromTicks(remaining * TimeSpan.TicksPerSecond / _time.TimestampFrequency));
        }

        return k;
    }

    private int FindFastHead(int have)
    {
        ReadOnlySpan<byte> head = [0xFF, 0xFF, 0xFD, 0x00, FrameConstants.BroadcastId];
        var at = _fast.AsSpan(0, have).IndexOf(head);
        return at;
    }

    /// <summary>Reads every module that did not answer on its own (up to the retry budget).</summary>
    private int AskMissing(ushort address, ReadOnlySpan<byte> ids, ReadOnlySpan<int> lengths, Span<byte> data, Span<Reply> replies, int answered)
    {
        var more = 0;
        var offset = 0;
        for (var i = 0; i < ids.Length; i++)
        {
            if (i >= answered)
            {
                _stats[ids[i]].Timeout();
                _stats[ids[i]].Retry();
                replies[i] = Read(ids[i], address, data.Slice(offset, lengths[i]));
                more += replies[i].Outcome == ReplyOutcome.Ok ? 1 : 0;
            }

            offset += lengths[i];
        }

        return more;
    }
}
