using System.Buffers.Binary;
using System.Text;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>A read position in a record's bytes, with MCAP's primitive encodings (the reading twin of <see cref="McapBuffer"/>).</summary>
internal struct McapCursor(ReadOnlyMemory<byte> bytes)
{
    private int _at;

    public readonly int Remaining => bytes.Length - _at;

    public readonly int Position => _at;

    public byte U8() => Take(1).Span[0];

    public ushort U16() => BinaryPrimitives.ReadUInt16LittleEndian(Take(2).Span);

    public uint U32() => BinaryPrimitives.ReadUInt32LittleEndian(Take(4).Span);

    public ulong U64() => BinaryPrimitives.ReadUInt64LittleEndian(Take(8).Span);

    public string String() => Encoding.UTF8.GetString(Take(checked((int)U32())).Span);

    public ReadOnlyMemory<byte> Bytes32() => Take(checked((int)U32()));

    public ReadOnlyMemory<byte> Rest() => Take(Remaining);

    public Dictionary<string, string> StringMap()
    {
        var end = checked((int)U32()) + _at;
        var map = new Dictionary<string, string>();
        while (_at < end)
        {
            map[String()] = String();
        }

        return map;
    }

    /// <summary>A <c>Map&lt;uint16, uint64&gt;</c>.</summary>
    public Dictionary<ushort, ulong> ChannelMap()
    {
        var end = checked((int)U32()) + _at;
        var map = new Dictionary<ushort, ulong>();
        while (_at < end)
        {
            map[U16()] = U64();
        }

        return map;
    }

    public ReadOnlyMemory<byte> Take(int count)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(count);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(count, Remaining);
        var slice = bytes.Slice(_at, count);
        _at += count;
        return slice;
    }
}
