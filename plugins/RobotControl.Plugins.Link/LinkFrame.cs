using System.Buffers.Binary;
using System.Text;

namespace RobotControl.Plugins.Link;

/// <summary>
/// The wire format of one sample (version 1), little-endian, <see cref="HeaderLength"/> bytes then the values
/// (the table is in docs/link.md):
/// version u8, flags u8 (0), signal count u16, layout u32 (FNV-1a of the signal names), sender u32, sequence i64,
/// loop time i64 (ns), wall time i64 (ns since the Unix epoch), then count × f64.
/// </summary>
internal static class LinkFrame
{
    /// <summary>The format version this code writes and reads.</summary>
    public const byte Version = 1;

    /// <summary>Bytes before the values.</summary>
    public const int HeaderLength = 36;

    /// <summary>The length of a frame of <paramref name="count"/> values.</summary>
    public static int Length(int count) => HeaderLength + (8 * count);

    /// <summary>FNV-1a (32 bit) of the signal names joined by commas: both ends of a link must carry the same list.</summary>
    public static uint Layout(IReadOnlyList<string> names)
    {
        var hash = 2166136261u;
        foreach (var b in Encoding.UTF8.GetBytes(string.Join(',', names)))
        {
            hash = (hash ^ b) * 16777619u;
        }

        return hash;
    }

    /// <summary>Writes a frame into <paramref name="frame"/> (exactly <see cref="Length"/> bytes). Allocation-free.</summary>
    public static void Write(Span<byte> frame, uint layout, uint sender, long sequence, long loopNs, long wallNs, ReadOnlySpan<double> values)
    {
        frame[0] = Version;
        frame[1] = 0;
        BinaryPrimitives.WriteUInt16LittleEndian(frame[2..], (ushort)values.Length);
        BinaryPrimitives.WriteUInt32LittleEndian(frame[4..], layout);
        BinaryPrimitives.WriteUInt32LittleEndian(frame[8..], sender);
        BinaryPrimitives.WriteInt64LittleEndian(frame[12..], sequence);
        BinaryPrimitives.WriteInt64LittleEndian(frame[20..], loopNs);
        BinaryPrimitives.WriteInt64LittleEndian(frame[28..], wallNs);
        for (var i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteDoubleLittleEndian(frame[(HeaderLength + (8 * i))..], values[i]);
        }
    }

    /// <summary>
    /// Decodes <paramref name="frame"/> into <paramref name="sample"/>; returns null, or what is wrong with the frame
    /// (then <paramref name="sample"/> is left as it was).
    /// </summary>
    public static string? Read(ReadOnlySpan<byte> frame, uint layout, int count, ref LinkSample sample)
    {
        if (frame.Length < HeaderLength)
        {
            return $"{frame.Length} bytes, shorter than the {HeaderLength}-byte header";
        }

        if (frame[0] != Version)
        {
            return $"format version {frame[0]}, this end reads version {Version}";
        }

        var frameCount = BinaryPrimitives.ReadUInt16LittleEndian(frame[2..]);
        if (frameCount != count)
        {
            return $"{frameCount} signals, this end has {count}";
        }

        if (frame.Length != Length(count))
        {
            return $"{frame.Length} bytes, {Length(count)} expected for {count} signals";
        }

        var frameLayout = BinaryPrimitives.ReadUInt32LittleEndian(frame[4..]);
        if (frameLayout != layout)
        {
            return $"signal names differ (layout {frameLayout:x8}, this end {layout:x8}): both ends must list the same signals in the same order";
        }

        sample.Sender = BinaryPrimitives.ReadUInt32LittleEndian(frame[8..]);
        sample.Sequence = BinaryPrimitives.ReadInt64LittleEndian(frame[12..]);
        sample.LoopNs = BinaryPrimitives.ReadInt64LittleEndian(frame[20..]);
        sample.WallNs = BinaryPrimitives.ReadInt64LittleEndian(frame[28..]);
        for (var i = 0; i < count; i++)
        {
            sample.Values[i] = BinaryPrimitives.ReadDoubleLittleEndian(frame[(HeaderLength + (8 * i))..]);
        }

        return null;
    }

    /// <summary>Nanoseconds since the Unix epoch.</summary>
    public static long UnixNs(DateTimeOffset time) => (time.UtcTicks - DateTimeOffset.UnixEpoch.UtcTicks) * 100;
}
