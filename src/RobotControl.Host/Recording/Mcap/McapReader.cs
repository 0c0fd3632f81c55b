using System.Buffers.Binary;
using System.Text;

namespace RobotControl.Host.Recording.Mcap;

/// <summary>
/// Reads an MCAP file front to back, as a streaming reader does: header, schemas, channels, messages (inside
/// uncompressed chunks, whose CRC is checked), attachments and metadata, up to the data end. A file cut short (a kill)
/// gives every message up to its last complete chunk and says where it stops (<see cref="McapContents.Truncated"/>).
/// What it cannot read is one line naming the file and the problem (<see cref="InvalidDataException"/>).
/// </summary>
public static class McapReader
{
    /// <summary>Reads <paramref name="path"/>.</summary>
    /// <exception cref="InvalidDataException">Not an MCAP file, a compressed chunk, or a record that does not parse or whose CRC is wrong.</exception>
    public static McapContents Read(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        var bytes = File.ReadAllBytes(path);
        var name = Path.GetFileName(path);
        if (bytes.Length < McapWriter.Magic.Length || !bytes.AsSpan(0, McapWriter.Magic.Length).SequenceEqual(McapWriter.Magic))
        {
            throw new InvalidDataException($"{path}: not an MCAP file (it does not start with the MCAP magic)");
        }

        var contents = new McapContents(path);
        var at = McapWriter.Magic.Length;
        while (at < bytes.Length)
        {
            if (bytes.Length - at < 9 || (long)BinaryPrimitives.ReadUInt64LittleEndian(bytes.AsSpan(at + 1)) > bytes.Length - at - 9)
            {
                contents.Truncated = $"{name}: cut short at byte {at} of {bytes.Length} (an incomplete record); read up to its last complete chunk";
                return contents;
            }

            var opcode = (McapOpcode)bytes[at];
            var length = (int)BinaryPrimitives.ReadUInt64LittleEndian(bytes.AsSpan(at + 1));
            var body = bytes.AsMemory(at + 9, length);
            try
            {
                if (Record(opcode, body, contents, name))
                {
                    contents.Complete = true;
                    return contents;
                }
            }
            catch (Exception ex) when (ex is ArgumentOutOfRangeException or IndexOutOfRangeException or DecoderFallbackException)
            {
                throw new InvalidDataException($"{path}: the {opcode} record at byte {at} does not parse ({ex.Message})");
            }

            at += 9 + length;
        }

        contents.Truncated = $"{name}: ends at byte {bytes.Length} without its data end and summary (cut short); read up to its last complete chunk";
        return contents;
    }

    /// <summary>Takes one record; true at the data end (the summary follows).</summary>
    private static bool Record(McapOpcode opcode, ReadOnlyMemory<byte> body, McapContents contents, string name)
    {
        var r = new Cursor(body);
        switch (opcode)
        {
            case McapOpcode.Header:
                contents.Profile = r.String();
                contents.Library = r.String();
                break;
            case McapOpcode.Schema:
                var id = r.U16();
                contents.Schemas[id] = new McapSchema(id, r.String(), r.String(), r.Bytes32().ToArray());
                break;
            case McapOpcode.Channel:
                var channel = r.U16();
                contents.Channels[channel] = new McapChannel(channel, r.U16(), r.String(), r.String());
                break;
            case McapOpcode.Message:
                var c = r.U16();
                r.U32();
                var logTime = r.U64();
                r.U64();
                contents.Messages.Add(new McapMessage(c, logTime, r.Rest()));
                break;
            case McapOpcode.Chunk:
                Chunk(ref r, contents, name);
                break;
            case McapOpcode.Attachment:
                r.U64();
                r.U64();
                var attachment = r.String();
                var media = r.String();
                var size = (int)r.U64();
                contents.Attachments[attachment] = Encoding.UTF8.GetString(r.Take(size).Span);
                break;
            case McapOpcode.Metadata:
                var metadata = r.String();
                contents.Metadata[metadata] = r.StringMap();
                break;
            case McapOpcode.DataEnd:
                return true;
        }

        return false;
    }

    private static void Chunk(ref Cursor r, McapContents contents, string name)
    {
        r.U64();
        r.U64();
        var size = r.U64();
        var crc = r.U32();
        var compression = r.String();
        if (compression.Length != 0)
        {
            throw new InvalidDataException($"{name}: a chunk is compressed with '{compression}'; robotctl reads uncompressed chunks (its own files)");
        }

        var records = r.Take((int)r.U64());
        if ((ulong)records.Length != size || (crc != 0 && Crc32.Compute(records.Span) != crc))
        {
            throw new InvalidDataException($"{name}: a chunk's CRC does not match its records (the file is damaged)");
        }

        var inner = new Cursor(records);
        while (inner.Remaining > 0)
        {
            var opcode = (McapOpcode)inner.U8();
            var length = (int)inner.U64();
            Record(opcode, inner.Take(length), contents, name);
        }
    }

    /// <summary>A read position in a record's bytes.</summary>
    private struct Cursor(ReadOnlyMemory<byte> bytes)
    {
        private int _at;

        public readonly int Remaining => bytes.Length - _at;

        public byte U8() => Take(1).Span[0];

        public ushort U16() => BinaryPrimitives.ReadUInt16LittleEndian(Take(2).Span);

        public uint U32() => BinaryPrimitives.ReadUInt32LittleEndian(Take(4).Span);

        public ulong U64() => BinaryPrimitives.ReadUInt64LittleEndian(Take(8).Span);

        public string String() => Encoding.UTF8.GetString(Take((int)U32()).Span);

        public ReadOnlyMemory<byte> Bytes32() => Take((int)U32());

        public ReadOnlyMemory<byte> Rest() => Take(Remaining);

        public Dictionary<string, string> StringMap()
        {
            var end = (int)U32() + _at;
            var map = new Dictionary<string, string>();
            while (_at < end)
            {
                map[String()] = String();
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
}

/// <summary>What <see cref="McapReader"/> read from a file.</summary>
public sealed class McapContents(string path)
{
    /// <summary>The file.</summary>
    public string Path { get; } = path;

    /// <summary>The header's profile.</summary>
    public string Profile { get; internal set; } = string.Empty;

    /// <summary>The header's library.</summary>
    public string Library { get; internal set; } = string.Empty;

    /// <summary>True when the data end was reached (a finished file).</summary>
    public bool Complete { get; internal set; }

    /// <summary>Where and why reading stopped early (a file cut short), or null.</summary>
    public string? Truncated { get; internal set; }

    /// <summary>Schemas by id.</summary>
    public Dictionary<ushort, McapSchema> Schemas { get; } = [];

    /// <summary>Channels by id.</summary>
    public Dictionary<ushort, McapChannel> Channels { get; } = [];

    /// <summary>Every message, in file order.</summary>
    public List<McapMessage> Messages { get; } = [];

    /// <summary>Attachments (text) by name.</summary>
    public Dictionary<string, string> Attachments { get; } = [];

    /// <summary>Metadata records by name.</summary>
    public Dictionary<string, Dictionary<string, string>> Metadata { get; } = [];
}

/// <summary>A schema record.</summary>
public sealed record McapSchema(ushort Id, string Name, string Encoding, byte[] Data);

/// <summary>A channel record.</summary>
public sealed record McapChannel(ushort Id, ushort SchemaId, string Topic, string MessageEncoding);

/// <summary>A message: its channel, log time (ns) and data.</summary>
public sealed record McapMessage(ushort ChannelId, ulong LogTimeNs, ReadOnlyMemory<byte> Data);
