using System.Buffers.Binary;
using System.Text;
using Microsoft.Win32.SafeHandles;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// An MCAP file opened for reading by its index, as an indexed reader does: the footer gives the summary section
/// (schemas, channels, statistics, chunk, attachment and metadata indexes), and a chunk is read only when its messages
/// are asked for, so opening a file of gigabytes and reading its middle costs a few reads. A file without a summary (cut
/// short by a kill, or written without one) is scanned record by record instead, up to its last complete chunk, and says
/// where it stops (<see cref="Truncated"/>). Every chunk read is checked against its CRC. Reads are positional, so
/// several threads may read one file. What it cannot read is one line naming the file and the problem
/// (<see cref="InvalidDataException"/>).
/// </summary>
public sealed class McapFile : IDisposable
{
    private const int RecordHeader = McapRecords.RecordHeader;
    private const int FooterRecord = RecordHeader + 8 + 8 + 4;
    private readonly McapRecords _records;
    private readonly string _name;
    private readonly long _length;
    private readonly Dictionary<ushort, McapSchema> _schemas = [];
    private readonly Dictionary<ushort, McapChannel> _channels = [];
    private readonly Dictionary<ushort, ulong> _counts = [];
    private readonly List<McapChunkInfo> _chunks = [];
    private readonly Dictionary<string, string> _attachments = [];
    private readonly Dictionary<string, IReadOnlyDictionary<string, string>> _metadata = [];

    private McapFile(string path, SafeFileHandle handle)
    {
        Path = path;
        _name = System.IO.Path.GetFileName(path);
        _records = new McapRecords(path, handle);
        _length = _records.Length;
    }

    /// <summary>The file.</summary>
    public string Path { get; }

    /// <summary>The header's profile.</summary>
    public string Profile { get; private set; } = string.Empty;

    /// <summary>The header's library.</summary>
    public string Library { get; private set; } = string.Empty;

    /// <summary>True when the file reaches its data end (a finished file).</summary>
    public bool Complete { get; private set; }

    /// <summary>True when the file was opened by its summary section (no scan).</summary>
    public bool Indexed { get; private set; }

    /// <summary>Where and why the file stops early (cut short), or null.</summary>
    public string? Truncated { get; private set; }

    /// <summary>Schemas by id.</summary>
    public IReadOnlyDictionary<ushort, McapSchema> Schemas => _schemas;

    /// <summary>Channels by id.</summary>
    public IReadOnlyDictionary<ushort, McapChannel> Channels => _channels;

    /// <summary>Messages per channel (the statistics, or counted by the scan).</summary>
    public IReadOnlyDictionary<ushort, ulong> MessageCounts => _counts;

    /// <summary>Messages in the file (every channel).</summary>
    public ulong MessageCount => _counts.Values.Aggregate(0UL, (a, c) => a + c);

    /// <summary>The chunks, by start time.</summary>
    public IReadOnlyList<McapChunkInfo> Chunks => _chunks;

    /// <summary>Log time of the first message (ns), or 0 for a file without messages.</summary>
    public ulong StartNs { get; private set; }

    /// <summary>Log time of the last message (ns), or 0 for a file without messages.</summary>
    public ulong EndNs { get; private set; }

    /// <summary>Attachments (text) by name.</summary>
    public IReadOnlyDictionary<string, string> Attachments => _attachments;

    /// <summary>Metadata records by name.</summary>
    public IReadOnlyDictionary<string, IReadOnlyDictionary<string, string>> Metadata => _metadata;

    /// <summary>Opens <paramref name="path"/>: its summary, or a scan when it has none.</summary>
    /// <exception cref="InvalidDataException">Missing, unreadable, not MCAP, damaged, or compressed in a way not read here (one line naming the file).</exception>
    public static McapFile Open(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        SafeFileHandle handle;
        try
        {
            handle = File.OpenHandle(path, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete, FileOptions.RandomAccess);
        }
        catch (Exception ex) when (ex is FileNotFoundException or DirectoryNotFoundException)
        {
            throw new InvalidDataException($"{path}: no such file", ex);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw new InvalidDataException($"{path}: cannot be read ({ex.Message})", ex);
        }

        var file = new McapFile(path, handle);
        try
        {
            file.Load();
            return file;
        }
        catch
        {
            handle.Dispose();
            throw;
        }
    }

    /// <summary>The channel of <paramref name="topic"/>, or null.</summary>
    public McapChannel? Channel(string topic) => _channels.Values.FirstOrDefault(c => c.Topic == topic);

    /// <summary>
    /// The messages on <paramref name="channels"/> (null: every channel) logged from <paramref name="fromNs"/> to
    /// <paramref name="toNs"/>, in log-time order (chunks that overlap in time are merged). Only the chunks that may
    /// hold them are read, one or a few at a time, as the sequence is enumerated.
    /// </summary>
    /// <exception cref="InvalidDataException">A chunk read on the way is damaged (its CRC) or does not parse.</exception>
    public IEnumerable<McapMessage> Messages(IReadOnlyCollection<ushort>? channels = null, ulong fromNs = 0, ulong toNs = ulong.MaxValue)
    {
        var wanted = _chunks.Where(c => c.EndNs >= fromNs && c.StartNs <= toNs && (channels is null || c.Channels is null || channels.Any(c.Channels.Contains))).ToList();
        var open = new PriorityQueue<ChunkCursor, (ulong Time, int Order)>();
        var next = 0;
        while (true)
        {
            while (next < wanted.Count && (!open.TryPeek(out _, out var head) || wanted[next].StartNs <= head.Time))
            {
                var messages = _records.ReadMessages(wanted[next], channels, fromNs, toNs);
                if (messages.Length > 0)
                {
                    open.Enqueue(new ChunkCursor(messages, next), (messages[0].LogTimeNs, next));
                }

                next++;
            }

            if (!open.TryDequeue(out var cursor, out _))
            {
                yield break;
            }

            yield return cursor.Messages[cursor.At++];
            if (cursor.At < cursor.Messages.Length)
            {
                open.Enqueue(cursor, (cursor.Messages[cursor.At].LogTimeNs, cursor.Order));
            }
        }
    }

    /// <inheritdoc />
    public void Dispose() => _records.Dispose();

    private void Load()
    {
        if (_length < McapWriter.Magic.Length || !_records.ReadBytes(0, McapWriter.Magic.Length).AsSpan().SequenceEqual(McapWriter.Magic))
        {
            throw new InvalidDataException($"{Path}: not an MCAP file (it does not start with the MCAP magic)");
        }

        if (!TryLoadSummary())
        {
            Scan();
        }

        _chunks.Sort((a, b) => a.StartNs != b.StartNs ? a.StartNs.CompareTo(b.StartNs) : a.Offset.CompareTo(b.Offset));
    }

    /// <summary>Reads the footer and the summary section it points at; false when the file has none (or is cut short).</summary>
    private bool TryLoadSummary()
    {
        var footerAt = _length - McapWriter.Magic.Length - FooterRecord;
        if (footerAt < McapWriter.Magic.Length)
        {
            return false;
        }

        var tail = _records.ReadBytes(footerAt, FooterRecord + McapWriter.Magic.Length);
        if (!tail.AsSpan(FooterRecord).SequenceEqual(McapWriter.Magic) || tail[0] != (byte)McapOpcode.Footer)
        {
            return false;
        }

        var summaryStart = BinaryPrimitives.ReadUInt64LittleEndian(tail.AsSpan(RecordHeader));
        var summaryCrc = BinaryPrimitives.ReadUInt32LittleEndian(tail.AsSpan(RecordHeader + 16));
        if (summaryStart == 0)
        {
            return false; // written without a summary: the scan reads it
        }

        if (summaryStart < (ulong)McapWriter.Magic.Length || summaryStart > (ulong)footerAt)
        {
            throw _records.Damaged($"its footer points at a summary at byte {summaryStart}, outside the file");
        }

        var summary = _records.ReadBytes((long)summaryStart, (int)(footerAt - (long)summaryStart));
        if (summaryCrc != 0 && Crc32.Final(Crc32.Update(Crc32.Update(Crc32.Initial, summary), tail.AsSpan(0, FooterRecord - 4))) != summaryCrc)
        {
            throw _records.Damaged("its summary section's CRC does not match (the file is damaged)");
        }

        var attachments = new List<(long Offset, int Length)>();
        var metadata = new List<(long Offset, int Length)>();
        var statistics = false;
        var chunkCount = 0u;
        _records.EachRecord(summary, (long)summaryStart, (opcode, body, at) =>
        {
            var r = new McapCursor(body);
            switch (opcode)
            {
                case McapOpcode.Schema or McapOpcode.Channel:
                    Definition(opcode, ref r);
                    break;
                case McapOpcode.Statistics:
                    statistics = true;
                    Statistics(ref r, out chunkCount);
                    break;
                case McapOpcode.ChunkIndex:
                    _chunks.Add(ChunkIndex(ref r));
                    break;
                case McapOpcode.AttachmentIndex:
                    attachments.Add(((long)r.U64(), checked((int)r.U64())));
                    break;
                case McapOpcode.MetadataIndex:
                    metadata.Add(((long)r.U64(), checked((int)r.U64())));
                    break;
            }
        });
        if (!statistics || _chunks.Count != chunkCount)
        {
            _chunks.Clear(); // a summary without the indexes this reader needs: read the file through
            _schemas.Clear();
            _channels.Clear();
            _counts.Clear();
            return false;
        }

        foreach (var (offset, length) in attachments.Concat(metadata))
        {
            _records.EachRecord(_records.ReadBytes(offset, length), offset, (opcode, body, _) => Outside(opcode, body));
        }

        ReadHeader();
        Complete = true;
        Indexed = true;
        return true;
    }

    /// <summary>Reads the file record by record (no summary): definitions, chunks (each read, checked and counted), attachments and metadata, to the data end or the last complete record.</summary>
    private void Scan()
    {
        var at = ReadHeader();
        var anyMessage = false;
        while (at < _length)
        {
            if (_length - at < RecordHeader)
            {
                break;
            }

            var head = _records.ReadBytes(at, RecordHeader);
            var length = BinaryPrimitives.ReadUInt64LittleEndian(head.AsSpan(1));
            if (length > (ulong)(_length - at - RecordHeader))
            {
                Truncated = $"{_name}: cut short at byte {at} of {_length} (an incomplete record); read up to its last complete chunk";
                return;
            }

            var opcode = (McapOpcode)head[0];
            switch (opcode)
            {
                case McapOpcode.DataEnd:
                    Complete = true;
                    return;
                case McapOpcode.Chunk:
                    var body = _records.ReadBytes(at + RecordHeader, checked((int)length));
                    var (start, end, records) = _records.OpenChunk(body, at);
                    var inChunk = new HashSet<ushort>();
                    _records.EachRecord(records, at, (inner, record, _) =>
                    {
                        var r = new McapCursor(record);
                        if (inner == McapOpcode.Message)
                        {
                            var channel = r.U16();
                            inChunk.Add(channel);
                            _counts[channel] = _counts.GetValueOrDefault(channel) + 1;
                        }
                        else
                        {
                            Definition(inner, ref r);
                        }
                    });
                    _chunks.Add(new McapChunkInfo(start, end, at, checked((int)(RecordHeader + (long)length)), inChunk));
                    if (inChunk.Count > 0)
                    {
                        StartNs = anyMessage ? Math.Min(StartNs, start) : start;
                        EndNs = anyMessage ? Math.Max(EndNs, end) : end;
                        anyMessage = true;
                    }

                    break;
                case McapOpcode.Schema or McapOpcode.Channel or McapOpcode.Attachment or McapOpcode.Metadata:
                    Outside(opcode, _records.ReadBytes(at + RecordHeader, checked((int)length)));
                    break;
            }

            at += RecordHeader + (long)length;
        }

        Truncated = $"{_name}: ends at byte {_length} without its data end and summary (cut short); read up to its last complete chunk";
    }

    /// <summary>Reads the header record; returns where the next record starts.</summary>
    private long ReadHeader()
    {
        long at = McapWriter.Magic.Length;
        if (_length - at < RecordHeader)
        {
            return _length;
        }

        var head = _records.ReadBytes(at, RecordHeader);
        var length = BinaryPrimitives.ReadUInt64LittleEndian(head.AsSpan(1));
        if (head[0] != (byte)McapOpcode.Header || length > (ulong)(_length - at - RecordHeader))
        {
            return head[0] == (byte)McapOpcode.Header ? _length : at;
        }

        var r = new McapCursor(_records.ReadBytes(at + RecordHeader, (int)length));
        _records.Parse(McapOpcode.Header, at, () =>
        {
            Profile = r.String();
            Library = r.String();
        });
        return at + RecordHeader + (long)length;
    }

    /// <summary>A schema, channel, attachment or metadata record outside a chunk.</summary>
    private void Outside(McapOpcode opcode, ReadOnlyMemory<byte> body)
    {
        var r = new McapCursor(body);
        switch (opcode)
        {
            case McapOpcode.Attachment:
                r.U64();
                r.U64();
                var name = r.String();
                r.String();
                var size = checked((int)r.U64());
                _attachments[name] = Encoding.UTF8.GetString(r.Take(size).Span);
                break;
            case McapOpcode.Metadata:
                var metadata = r.String();
                _metadata[metadata] = r.StringMap();
                break;
            default:
                Definition(opcode, ref r);
                break;
        }
    }

    private void Definition(McapOpcode opcode, ref McapCursor r)
    {
        if (opcode == McapOpcode.Schema)
        {
            var id = r.U16();
            _schemas[id] = new McapSchema(id, r.String(), r.String(), r.Bytes32().ToArray());
        }
        else if (opcode == McapOpcode.Channel)
        {
            var id = r.U16();
            _channels[id] = new McapChannel(id, r.U16(), r.String(), r.String());
        }
    }

    private void Statistics(ref McapCursor r, out uint chunkCount)
    {
        r.U64();
        r.U16();
        r.U32();
        r.U32();
        r.U32();
        chunkCount = r.U32();
        StartNs = r.U64();
        EndNs = r.U64();
        foreach (var (channel, count) in r.ChannelMap())
        {
            _counts[channel] = count;
        }
    }

    private static McapChunkInfo ChunkIndex(ref McapCursor r)
    {
        var start = r.U64();
        var end = r.U64();
        var offset = (long)r.U64();
        var length = checked((int)r.U64());
        var channels = r.ChannelMap().Keys.ToHashSet();
        return new McapChunkInfo(start, end, offset, length, channels);
    }

    /// <summary>One chunk's messages, being merged.</summary>
    private sealed class ChunkCursor(McapMessage[] messages, int order)
    {
        public McapMessage[] Messages { get; } = messages;

        public int Order { get; } = order;

        public int At { get; set; }
    }
}

/// <summary>Where a chunk is and what it holds.</summary>
/// <param name="StartNs">Log time of its first message.</param>
/// <param name="EndNs">Log time of its last message.</param>
/// <param name="Offset">Where its record starts in the file.</param>
/// <param name="Length">Its record's length, opcode and length prefix included.</param>
/// <param name="Channels">The channels it holds messages of (null: not known; read it to find out).</param>
public sealed record McapChunkInfo(ulong StartNs, ulong EndNs, long Offset, int Length, IReadOnlySet<ushort>? Channels);

/// <summary>A schema record.</summary>
public sealed record McapSchema(ushort Id, string Name, string Encoding, byte[] Data);

/// <summary>A channel record.</summary>
public sealed record McapChannel(ushort Id, ushort SchemaId, string Topic, string MessageEncoding);

/// <summary>A message: its channel, log time (ns) and data.</summary>
public sealed record McapMessage(ushort ChannelId, ulong LogTimeNs, ReadOnlyMemory<byte> Data);
