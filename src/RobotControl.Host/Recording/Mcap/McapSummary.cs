namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// What an <see cref="McapWriter"/> has written, kept for the summary section: schemas, channels, message counts and
/// time range, chunk, attachment and metadata indexes; and the writing of that section (groups and their offsets).
/// </summary>
internal sealed class McapSummary
{
    public List<SchemaEntry> Schemas { get; } = [];

    public List<ChannelEntry> Channels { get; } = [];

    public Dictionary<ushort, ulong> MessageCounts { get; } = [];

    public List<ChunkEntry> Chunks { get; } = [];

    public List<AttachmentEntry> Attachments { get; } = [];

    public List<MetadataEntry> Metadata { get; } = [];

    public ulong StartTime { get; private set; }

    public ulong EndTime { get; private set; }

    private bool _anyMessage;

    /// <summary>Widens the message time range to <paramref name="time"/>.</summary>
    public void Seen(ulong time)
    {
        StartTime = _anyMessage ? Math.Min(StartTime, time) : time;
        EndTime = _anyMessage ? Math.Max(EndTime, time) : time;
        _anyMessage = true;
    }

    public static void WriteSchema(McapBuffer b, SchemaEntry s)
    {
        var mark = b.BeginRecord(McapOpcode.Schema);
        b.U16(s.Id);
        b.String(s.Name);
        b.String(s.Encoding);
        b.Bytes32(s.Data);
        b.EndRecord(mark);
    }

    public static void WriteChannel(McapBuffer b, ChannelEntry c)
    {
        var mark = b.BeginRecord(McapOpcode.Channel);
        b.U16(c.Id);
        b.U16(c.SchemaId);
        b.String(c.Topic);
        b.String(c.MessageEncoding);
        b.StringMap(c.Metadata);
        b.EndRecord(mark);
    }

    /// <summary>
    /// Writes the summary section into <paramref name="b"/> (empty; the section starts at file offset
    /// <paramref name="fileOffset"/>): one group per record type, then a summary offset per group.
    /// </summary>
    public void WriteSummary(McapBuffer b, long fileOffset, out ulong summaryStart, out ulong summaryOffsetStart)
    {
        var groups = new List<(McapOpcode Opcode, int Start, int Length)>();
        void Group(McapOpcode opcode, Action write)
        {
            var start = b.Length;
            write();
            if (b.Length > start)
            {
                groups.Add((opcode, start, b.Length - start));
            }
        }

        Group(McapOpcode.Schema, () => Schemas.ForEach(s => WriteSchema(b, s)));
        Group(McapOpcode.Channel, () => Channels.ForEach(c => WriteChannel(b, c)));
        Group(McapOpcode.Statistics, () => WriteStatistics(b));
        Group(McapOpcode.ChunkIndex, () => Chunks.ForEach(c => WriteChunkIndex(b, c)));
        Group(McapOpcode.AttachmentIndex, () => Attachments.ForEach(a => WriteAttachmentIndex(b, a)));
        Group(McapOpcode.MetadataIndex, () => Metadata.ForEach(m => WriteMetadataIndex(b, m)));
        summaryStart = (ulong)fileOffset;
        summaryOffsetStart = (ulong)(fileOffset + b.Length);
        foreach (var (opcode, start, length) in groups)
        {
            var mark = b.BeginRecord(McapOpcode.SummaryOffset);
            b.U8((byte)opcode);
            b.U64((ulong)(fileOffset + start));
            b.U64((ulong)length);
            b.EndRecord(mark);
        }
    }

    private void WriteStatistics(McapBuffer b)
    {
        var mark = b.BeginRecord(McapOpcode.Statistics);
        b.U64(MessageCounts.Values.Aggregate(0UL, (a, c) => a + c));
        b.U16((ushort)Schemas.Count);
        b.U32((uint)Channels.Count);
        b.U32((uint)Attachments.Count);
        b.U32((uint)Metadata.Count);
        b.U32((uint)Chunks.Count);
        b.U64(StartTime);
        b.U64(EndTime);
        var map = b.BeginLength32();
        foreach (var (channel, count) in MessageCounts.OrderBy(p => p.Key))
        {
            b.U16(channel);
            b.U64(count);
        }

        b.EndLength32(map);
        b.EndRecord(mark);
    }

    private static void WriteChunkIndex(McapBuffer b, ChunkEntry c)
    {
        var mark = b.BeginRecord(McapOpcode.ChunkIndex);
        b.U64(c.Start);
        b.U64(c.End);
        b.U64(c.Offset);
        b.U64(c.Length);
        var map = b.BeginLength32();
        foreach (var (channel, offset) in c.MessageIndexOffsets.OrderBy(p => p.Key))
        {
            b.U16(channel);
            b.U64(offset);
        }

        b.EndLength32(map);
        b.U64(c.MessageIndexLength);
        b.String(c.Compression);
        b.U64(c.StoredSize);
        b.U64(c.RecordsSize);
        b.EndRecord(mark);
    }

    private static void WriteAttachmentIndex(McapBuffer b, AttachmentEntry a)
    {
        var mark = b.BeginRecord(McapOpcode.AttachmentIndex);
        b.U64(a.Offset);
        b.U64(a.Length);
        b.U64(a.LogTime);
        b.U64(a.LogTime);
        b.U64(a.DataSize);
        b.String(a.Name);
        b.String(a.MediaType);
        b.EndRecord(mark);
    }

    private static void WriteMetadataIndex(McapBuffer b, MetadataEntry m)
    {
        var mark = b.BeginRecord(McapOpcode.MetadataIndex);
        b.U64(m.Offset);
        b.U64(m.Length);
        b.String(m.Name);
        b.EndRecord(mark);
    }

    public sealed record SchemaEntry(ushort Id, string Name, string Encoding, byte[] Data);

    public sealed record ChannelEntry(ushort Id, ushort SchemaId, string Topic, string MessageEncoding, IReadOnlyDictionary<string, string> Metadata);

    public sealed record ChunkEntry(ulong Start, ulong End, ulong Offset, ulong Length, Dictionary<ushort, ulong> MessageIndexOffsets, ulong MessageIndexLength, string Compression, ulong StoredSize, ulong RecordsSize);

    public sealed record AttachmentEntry(ulong Offset, ulong Length, ulong LogTime, ulong DataSize, string Name, string MediaType);

    public sealed record MetadataEntry(ulong Offset, ulong Length, string Name);
}
