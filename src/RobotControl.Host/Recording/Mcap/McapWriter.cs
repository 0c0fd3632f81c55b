namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// Writes an MCAP file: magic, header, schemas and channels, messages in chunks (uncompressed or zstd, each with the
/// CRC-32 of its records and followed by its message indexes), attachments and metadata, then the data end, the summary section (schemas,
/// channels, statistics, chunk/attachment/metadata indexes, summary offsets) and the footer. A chunk goes to the stream
/// whole and the stream is flushed after it, so a file cut short (a kill, a crash) holds every message up to its last
/// complete chunk, which a streaming reader reads. One thread writes (the recorder's writer thread); an
/// <see cref="IOException"/> from the stream (a full disk) propagates to it.
/// </summary>
public sealed class McapWriter : IDisposable
{
    /// <summary>The eight bytes that open and close an MCAP file.</summary>
    public static ReadOnlySpan<byte> Magic => [0x89, (byte)'M', (byte)'C', (byte)'A', (byte)'P', 0x30, (byte)'\r', (byte)'\n'];

    private readonly Stream _stream;
    private readonly McapBuffer _out = new(1 << 16);
    private readonly McapBuffer _chunk;
    private readonly int _chunkBytes;
    private readonly ulong _chunkSpanNs;
    private readonly McapSummary _summary = new();
    private readonly McapCompression _compression;
    private readonly Dictionary<ushort, List<(ulong Time, ulong Offset)>> _chunkIndexes = [];
    private readonly Dictionary<ushort, uint> _sequences = [];
    private long _position;
    private uint _dataCrc = Crc32.Initial;
    private ulong _chunkStart;
    private ulong _chunkEnd;
    private int _chunkMessages;
    private bool _finished;

    /// <summary>Starts a file on <paramref name="stream"/> (written from its current position, taken as offset 0).</summary>
    /// <param name="stream">Where the file goes; disposed with the writer.</param>
    /// <param name="profile">The header's profile ("" for none).</param>
    /// <param name="library">The header's library name.</param>
    /// <param name="chunkBytes">A chunk is closed once its records reach this size.</param>
    /// <param name="chunkSpan">A chunk is closed once its messages span this much log time (bounds what a kill loses).</param>
    /// <param name="compression">The chunks' compression: <see cref="McapCompression.None"/> or <see cref="McapCompression.Zstd"/>.</param>
    public McapWriter(Stream stream, string profile, string library, int chunkBytes = 512 * 1024, TimeSpan? chunkSpan = null, string compression = McapCompression.None)
    {
        ArgumentNullException.ThrowIfNull(stream);
        ArgumentNullException.ThrowIfNull(profile);
        ArgumentNullException.ThrowIfNull(library);
        ArgumentOutOfRangeException.ThrowIfLessThan(chunkBytes, 64);
        _compression = new McapCompression(compression);
        _stream = stream;
        _chunkBytes = chunkBytes;
        _chunk = new McapBuffer(chunkBytes + (chunkBytes / 4));
        _chunkSpanNs = (ulong)(chunkSpan ?? TimeSpan.FromSeconds(1)).Ticks * 100;
        _out.Raw(Magic);
        var mark = _out.BeginRecord(McapOpcode.Header);
        _out.String(profile);
        _out.String(library);
        _out.EndRecord(mark);
        EmitData();
    }

    /// <summary>Messages written so far, per channel.</summary>
    public IReadOnlyDictionary<ushort, ulong> MessageCounts => _summary.MessageCounts;

    /// <summary>Messages written so far, per topic.</summary>
    public IReadOnlyDictionary<string, ulong> CountsByTopic => _summary.Channels.ToDictionary(c => c.Topic, c => _summary.MessageCounts[c.Id]);

    /// <summary>Chunks written so far.</summary>
    public int ChunkCount => _summary.Chunks.Count;

    /// <summary>Bytes handed to the stream so far.</summary>
    public long Position => _position;

    /// <summary>Adds a schema (written at once, outside any chunk); returns its id.</summary>
    public ushort AddSchema(string name, string encoding, ReadOnlySpan<byte> data)
    {
        var schema = new McapSummary.SchemaEntry((ushort)(_summary.Schemas.Count + 1), name, encoding, data.ToArray());
        _summary.Schemas.Add(schema);
        CloseChunk();
        McapSummary.WriteSchema(_out, schema);
        EmitData();
        return schema.Id;
    }

    /// <summary>Adds a channel on schema <paramref name="schemaId"/> (written at once, outside any chunk); returns its id.</summary>
    public ushort AddChannel(ushort schemaId, string topic, string messageEncoding, IReadOnlyDictionary<string, string>? metadata = null)
    {
        if (schemaId != 0 && _summary.Schemas.All(s => s.Id != schemaId))
        {
            throw new ArgumentException($"no schema {schemaId}", nameof(schemaId));
        }

        var channel = new McapSummary.ChannelEntry((ushort)_summary.Channels.Count, schemaId, topic, messageEncoding, metadata ?? new Dictionary<string, string>());
        _summary.Channels.Add(channel);
        _summary.MessageCounts[channel.Id] = 0;
        CloseChunk();
        McapSummary.WriteChannel(_out, channel);
        EmitData();
        return channel.Id;
    }

    /// <summary>Writes message <paramref name="data"/> on <paramref name="channelId"/> at <paramref name="logTimeNs"/> into the open chunk.</summary>
    public void WriteMessage(ushort channelId, ulong logTimeNs, ReadOnlySpan<byte> data)
    {
        ObjectDisposedException.ThrowIf(_finished, this);
        if (!_summary.MessageCounts.TryGetValue(channelId, out var count))
        {
            throw new ArgumentException($"no channel {channelId}", nameof(channelId));
        }

        if (_chunkMessages == 0)
        {
            _chunkStart = logTimeNs;
            _chunkEnd = logTimeNs;
        }

        var sequence = _sequences.GetValueOrDefault(channelId);
        _sequences[channelId] = sequence + 1;
        if (!_chunkIndexes.TryGetValue(channelId, out var index))
        {
            _chunkIndexes[channelId] = index = [];
        }

        index.Add((logTimeNs, (ulong)_chunk.Length));
        var mark = _chunk.BeginRecord(McapOpcode.Message);
        _chunk.U16(channelId);
        _chunk.U32(sequence);
        _chunk.U64(logTimeNs);
        _chunk.U64(logTimeNs);
        _chunk.Raw(data);
        _chunk.EndRecord(mark);
        _chunkMessages++;
        _chunkStart = Math.Min(_chunkStart, logTimeNs);
        _chunkEnd = Math.Max(_chunkEnd, logTimeNs);
        _summary.MessageCounts[channelId] = count + 1;
        _summary.Seen(logTimeNs);
        if (_chunk.Length >= _chunkBytes || _chunkEnd - _chunkStart >= _chunkSpanNs)
        {
            CloseChunk();
        }
    }

    /// <summary>Writes an attachment (a file carried in the recording) outside any chunk.</summary>
    public void AddAttachment(string name, string mediaType, ReadOnlySpan<byte> data, ulong logTimeNs)
    {
        CloseChunk();
        var start = _out.Length;
        var mark = _out.BeginRecord(McapOpcode.Attachment);
        _out.U64(logTimeNs);
        _out.U64(logTimeNs);
        _out.String(name);
        _out.String(mediaType);
        _out.U64((ulong)data.Length);
        _out.Raw(data);
        _out.U32(Crc32.Compute(_out.Written[mark..]));
        _out.EndRecord(mark);
        _summary.Attachments.Add(new McapSummary.AttachmentEntry((ulong)(_position + start), (ulong)(_out.Length - start), logTimeNs, (ulong)data.Length, name, mediaType));
        EmitData();
    }

    /// <summary>Writes a metadata record (named key-value pairs) outside any chunk.</summary>
    public void AddMetadata(string name, IReadOnlyDictionary<string, string> values)
    {
        CloseChunk();
        var start = _out.Length;
        var mark = _out.BeginRecord(McapOpcode.Metadata);
        _out.String(name);
        _out.StringMap(values);
        _out.EndRecord(mark);
        _summary.Metadata.Add(new McapSummary.MetadataEntry((ulong)(_position + start), (ulong)(_out.Length - start), name));
        EmitData();
    }

    /// <summary>Writes the open chunk (if it holds a message) and its message indexes, and flushes the stream.</summary>
    public void CloseChunk()
    {
        if (_chunkMessages == 0)
        {
            return;
        }

        var records = _chunk.Written;
        var stored = _compression.Compress(records);
        var chunkOffset = _position;
        var mark = _out.BeginRecord(McapOpcode.Chunk);
        _out.U64(_chunkStart);
        _out.U64(_chunkEnd);
        _out.U64((ulong)records.Length);
        _out.U32(Crc32.Compute(records)); // of the records, before compression
        _out.String(_compression.Name);
        _out.U64((ulong)stored.Length);
        _out.Raw(stored);
        _out.EndRecord(mark);
        var chunkLength = _out.Length;
        var indexOffsets = new Dictionary<ushort, ulong>();
        foreach (var (channel, entries) in _chunkIndexes)
        {
            if (entries.Count == 0)
            {
                continue;
            }

            indexOffsets[channel] = (ulong)(chunkOffset + _out.Length);
            var m = _out.BeginRecord(McapOpcode.MessageIndex);
            _out.U16(channel);
            var array = _out.BeginLength32();
            foreach (var (time, offset) in entries)
            {
                _out.U64(time);
                _out.U64(offset);
            }

            _out.EndLength32(array);
            _out.EndRecord(m);
            entries.Clear();
        }

        _summary.Chunks.Add(new McapSummary.ChunkEntry(_chunkStart, _chunkEnd, (ulong)chunkOffset, (ulong)chunkLength, indexOffsets, (ulong)(_out.Length - chunkLength), _compression.Name, (ulong)stored.Length, (ulong)records.Length));
        _chunk.Clear();
        _chunkMessages = 0;
        EmitData();
        _stream.Flush();
    }

    /// <summary>Closes the last chunk and writes the data end, the summary section, the footer and the closing magic.</summary>
    public void Finish()
    {
        if (_finished)
        {
            return;
        }

        CloseChunk();
        var mark = _out.BeginRecord(McapOpcode.DataEnd);
        _out.U32(Crc32.Final(_dataCrc)); // every byte before the data end record
        _out.EndRecord(mark);
        Emit();
        _summary.WriteSummary(_out, _position, out var summaryStart, out var summaryOffsetStart);
        _out.U8((byte)McapOpcode.Footer);
        _out.U64(8 + 8 + 4); // the footer's length is fixed: known before the CRC that covers it
        _out.U64(summaryStart);
        _out.U64(summaryOffsetStart);
        _out.U32(Crc32.Compute(_out.Written));
        _out.Raw(Magic);
        Emit();
        _stream.Flush();
        _finished = true;
    }

    /// <inheritdoc />
    public void Dispose()
    {
        _stream.Dispose();
        _compression.Dispose();
    }

    /// <summary>Writes what <see cref="_out"/> holds as part of the data section (its CRC runs over it).</summary>
    private void EmitData()
    {
        _dataCrc = Crc32.Update(_dataCrc, _out.Written);
        Emit();
    }

    private void Emit()
    {
        _stream.Write(_out.Written);
        _position += _out.Length;
        _out.Clear();
    }
}
