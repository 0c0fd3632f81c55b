using System.Buffers.Binary;
using System.Text;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// A growable byte buffer with MCAP's primitive encodings (little-endian integers, <c>uint32</c>-prefixed strings,
/// byte-length-prefixed maps and records with an opcode and a <c>uint64</c> length). Reused between records: it grows
/// to the largest record and then allocates nothing.
/// </summary>
public sealed class McapBuffer
{
    private byte[] _bytes;

    /// <summary>Creates a buffer of <paramref name="capacity"/> bytes to start with.</summary>
    public McapBuffer(int capacity = 4096)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 16);
        _bytes = new byte[capacity];
    }

    /// <summary>Bytes written so far.</summary>
    public int Length { get; private set; }

    /// <summary>The bytes written so far.</summary>
    public ReadOnlySpan<byte> Written => _bytes.AsSpan(0, Length);

    /// <summary>Forgets what was written (keeps the capacity).</summary>
    public void Clear() => Length = 0;

    /// <summary>Writes one byte.</summary>
    public void U8(byte value) => Take(1)[0] = value;

    /// <summary>Writes a little-endian <c>uint16</c>.</summary>
    public void U16(ushort value) => BinaryPrimitives.WriteUInt16LittleEndian(Take(2), value);

    /// <summary>Writes a little-endian <c>uint32</c>.</summary>
    public void U32(uint value) => BinaryPrimitives.WriteUInt32LittleEndian(Take(4), value);

    /// <summary>Writes a little-endian <c>uint64</c>.</summary>
    public void U64(ulong value) => BinaryPrimitives.WriteUInt64LittleEndian(Take(8), value);

    /// <summary>Writes raw bytes.</summary>
    public void Raw(ReadOnlySpan<byte> bytes) => bytes.CopyTo(Take(bytes.Length));

    /// <summary>Writes a string: <c>uint32</c> byte length, then UTF-8.</summary>
    public void String(string value)
    {
        var count = Encoding.UTF8.GetByteCount(value);
        U32((uint)count);
        Encoding.UTF8.GetBytes(value, Take(count));
    }

    /// <summary>Writes bytes with a <c>uint32</c> length prefix.</summary>
    public void Bytes32(ReadOnlySpan<byte> bytes)
    {
        U32((uint)bytes.Length);
        Raw(bytes);
    }

    /// <summary>Starts a <c>uint32</c> byte-length prefix (a map or an array); returns where to finish it.</summary>
    public int BeginLength32()
    {
        Take(4);
        return Length;
    }

    /// <summary>Fills the prefix begun at <paramref name="mark"/> with the bytes written since.</summary>
    public void EndLength32(int mark) => BinaryPrimitives.WriteUInt32LittleEndian(_bytes.AsSpan(mark - 4, 4), (uint)(Length - mark));

    /// <summary>Starts a record: its opcode and a length to be filled by <see cref="EndRecord"/>.</summary>
    public int BeginRecord(McapOpcode opcode)
    {
        U8((byte)opcode);
        Take(8);
        return Length;
    }

    /// <summary>Fills the length of the record begun at <paramref name="mark"/>.</summary>
    public void EndRecord(int mark) => BinaryPrimitives.WriteUInt64LittleEndian(_bytes.AsSpan(mark - 8, 8), (ulong)(Length - mark));

    /// <summary>Writes a <c>Map&lt;string, string&gt;</c>.</summary>
    public void StringMap(IEnumerable<KeyValuePair<string, string>> map)
    {
        var mark = BeginLength32();
        foreach (var (key, value) in map)
        {
            String(key);
            String(value);
        }

        EndLength32(mark);
    }

    private Span<byte> Take(int count)
    {
        if (Length + count > _bytes.Length)
        {
            Array.Resize(ref _bytes, Math.Max(_bytes.Length * 2, Length + count));
        }

        var span = _bytes.AsSpan(Length, count);
        Length += count;
        return span;
    }
}
