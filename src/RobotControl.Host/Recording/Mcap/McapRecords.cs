using System.Text;
using Microsoft.Win32.SafeHandles;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// The bytes of an open MCAP file, read by position (so several threads may read at once): records and the records
/// inside a chunk, a chunk's messages, each chunk checked against its CRC (and decompressed) as it is read. What does
/// not parse is one line naming the file, the record and its byte.
/// </summary>
internal sealed class McapRecords(string path, SafeFileHandle handle) : IDisposable
{
    /// <summary>A record's opcode and length.</summary>
    public const int RecordHeader = 1 + 8;

    /// <summary>The file's length, bytes.</summary>
    public long Length { get; } = RandomAccess.GetLength(handle);

    /// <summary>The messages of <paramref name="chunk"/> on <paramref name="channels"/> within the times, by log time.</summary>
    public McapMessage[] ReadMessages(McapChunkInfo chunk, IReadOnlyCollection<ushort>? channels, ulong fromNs, ulong toNs)
    {
        var record = ReadBytes(chunk.Offset, chunk.Length);
        if (record[0] != (byte)McapOpcode.Chunk)
        {
            throw Damaged($"no chunk at byte {chunk.Offset}, where its index puts one");
        }

        var (_, _, records) = OpenChunk(record.AsMemory(RecordHeader), chunk.Offset);
        var messages = new List<McapMessage>();
        EachRecord(records, chunk.Offset, (opcode, body, _) =>
        {
            if (opcode != McapOpcode.Message)
            {
                return;
            }

            var r = new McapCursor(body);
            var channel = r.U16();
            r.U32();
            var logTime = r.U64();
            r.U64();
            if (logTime >= fromNs && logTime <= toNs && (channels is null || channels.Contains(channel)))
            {
                messages.Add(new McapMessage(channel, logTime, r.Rest()));
            }
        });
        return [.. messages.OrderBy(m => m.LogTimeNs)]; // stable: equal times keep the file's order
    }

    /// <summary>A chunk record's times and records, checked against its CRC.</summary>
    public (ulong Start, ulong End, ReadOnlyMemory<byte> Records) OpenChunk(ReadOnlyMemory<byte> body, long at)
    {
        ulong start = 0, end = 0;
        var records = ReadOnlyMemory<byte>.Empty;
        Parse(McapOpcode.Chunk, at, () =>
        {
            var r = new McapCursor(body);
            start = r.U64();
            end = r.U64();
            var size = r.U64();
            var crc = r.U32();
            var compression = r.String();
            records = McapCompression.Decompress(compression, r.Take(checked((int)r.U64())), size, what => Damaged($"the chunk at byte {at}: {what}"));
            if ((ulong)records.Length != size || (crc != 0 && Crc32.Compute(records.Span) != crc))
            {
                throw Damaged($"the chunk at byte {at}: its CRC does not match its records (the file is damaged)");
            }
        });
        return (start, end, records);
    }

    /// <summary>Calls <paramref name="take"/> for each record in <paramref name="bytes"/> (which start at file byte <paramref name="at"/>).</summary>
    public void EachRecord(ReadOnlyMemory<byte> bytes, long at, Action<McapOpcode, ReadOnlyMemory<byte>, long> take)
    {
        var r = new McapCursor(bytes);
        while (r.Remaining > 0)
        {
            var start = at + r.Position;
            var opcode = McapOpcode.Header;
            var body = ReadOnlyMemory<byte>.Empty;
            Parse(McapOpcode.Header, start, () =>
            {
                opcode = (McapOpcode)r.U8();
                body = r.Take(checked((int)r.U64()));
            });
            Parse(opcode, start, () => take(opcode, body, start));
        }
    }

    /// <summary>Runs <paramref name="parse"/>, turning a record that does not parse into one line naming it.</summary>
    public void Parse(McapOpcode opcode, long at, Action parse)
    {
        try
        {
            parse();
        }
        catch (Exception ex) when (ex is ArgumentOutOfRangeException or IndexOutOfRangeException or DecoderFallbackException or OverflowException)
        {
            throw new InvalidDataException($"{path}: the {opcode} record at byte {at} does not parse ({ex.Message})", ex);
        }
    }

    public byte[] ReadBytes(long offset, int count)
    {
        if (offset < 0 || count < 0 || offset + count > Length)
        {
            throw Damaged($"a record at byte {offset} runs past the end of the file");
        }

        var bytes = GC.AllocateUninitializedArray<byte>(count);
        var done = 0;
        while (done < count)
        {
            var read = RandomAccess.Read(handle, bytes.AsSpan(done), offset + done);
            if (read == 0)
            {
                throw Damaged($"it ended while byte {offset + done} was being read");
            }

            done += read;
        }

        return bytes;
    }

    public InvalidDataException Damaged(string what) => new($"{path}: {what}");

    /// <inheritdoc />
    public void Dispose() => handle.Dispose();
}
