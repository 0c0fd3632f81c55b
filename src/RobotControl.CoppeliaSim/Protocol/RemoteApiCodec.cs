using System.Formats.Cbor;

namespace RobotControl.CoppeliaSim.Protocol;

/// <summary>
/// CBOR encoding of requests and decoding of replies. Values map as: null -> <c>"_*NIL*_"</c>, bool, integers,
/// double (64-bit float), string, byte[] (byte string), lists (array), string-keyed dictionaries (map); decoding maps
/// back, <c>"_*NIL*_"</c> and CBOR null to null, integers to long and floats to double.
/// </summary>
public static class RemoteApiCodec
{
    /// <summary>Client language sent on first contact.</summary>
    public const string Language = "csharp";

    /// <summary>The CBOR bytes of <paramref name="request"/>.</summary>
    public static byte[] Encode(RemoteApiRequest request)
    {
        ArgumentNullException.ThrowIfNull(request);
        var writer = new CborWriter(CborConformanceMode.Lax);
        var first = request.FirstContactTimeoutSeconds is not null;
        writer.WriteStartMap(first ? 7 : 4);
        writer.WriteTextString("func");
        writer.WriteTextString(request.Func);
        writer.WriteTextString("args");
        WriteArray(writer, request.Args);
        writer.WriteTextString("argsL");
        writer.WriteInt32(request.Args.Count);
        writer.WriteTextString("uuid");
        writer.WriteTextString(request.Uuid);
        if (request.FirstContactTimeoutSeconds is { } timeout)
        {
            writer.WriteTextString("ver");
            writer.WriteInt32(RemoteApiWords.ProtocolVersion);
            writer.WriteTextString("lang");
            writer.WriteTextString(Language);
            writer.WriteTextString("timeout");
            writer.WriteInt32(timeout);
        }

        writer.WriteEndMap();
        return writer.Encode();
    }

    /// <summary>Decodes a reply.</summary>
    /// <exception cref="FormatException">Not a CBOR map of the expected shape.</exception>
    public static RemoteApiReply DecodeReply(ReadOnlyMemory<byte> bytes)
    {
        var value = Decode(bytes);
        if (value is not IReadOnlyDictionary<string, object?> map)
        {
            throw new FormatException("reply is not a CBOR map");
        }

        IReadOnlyList<object?> List(string key) => map.TryGetValue(key, out var v) && v is IReadOnlyList<object?> l ? l : [];
        string? Text(string key) => map.TryGetValue(key, out var v) ? v as string ?? v?.ToString() : null;
        var error = Text("err");
        return new RemoteApiReply(List("ret"), error is null ? null : RemoteApiWords.Unescape(error), Text("func"), List("args"));
    }

    /// <summary>Decodes one CBOR value (the fake server in the tests decodes requests with it).</summary>
    /// <exception cref="FormatException">Malformed CBOR.</exception>
    public static object? Decode(ReadOnlyMemory<byte> bytes)
    {
        try
        {
            var reader = new CborReader(bytes, CborConformanceMode.Lax);
            var value = ReadValue(reader);
            if (reader.BytesRemaining != 0)
            {
                throw new FormatException($"{reader.BytesRemaining} bytes after the CBOR value");
            }

            return value;
        }
        catch (CborContentException ex)
        {
            throw new FormatException($"malformed CBOR: {ex.Message}", ex);
        }
        catch (InvalidOperationException ex)
        {
            throw new FormatException($"malformed CBOR: {ex.Message}", ex);
        }
    }

    /// <summary>Writes one value (see the class remarks for the mapping).</summary>
    public static void WriteValue(CborWriter writer, object? value)
    {
        ArgumentNullException.ThrowIfNull(writer);
        switch (value)
        {
            case null:
                writer.WriteTextString(RemoteApiWords.Nil);
                break;
            case bool b:
                writer.WriteBoolean(b);
                break;
            case int i:
                writer.WriteInt64(i);
                break;
            case long l:
                writer.WriteInt64(l);
                break;
            case double d:
                WriteFloat64(writer, d);
                break;
            case string s:
                writer.WriteTextString(s);
                break;
            case byte[] bytes:
                writer.WriteByteString(bytes);
                break;
            case IReadOnlyDictionary<string, object?> map:
                writer.WriteStartMap(map.Count);
                foreach (var (key, item) in map)
                {
                    writer.WriteTextString(key);
                    WriteValue(writer, item);
                }

                writer.WriteEndMap();
                break;
            case IReadOnlyList<object?> list:
                WriteArray(writer, list);
                break;
            default:
                throw new ArgumentException($"cannot send a {value.GetType().Name} to CoppeliaSim", nameof(value));
        }
    }

    // CborWriter.WriteDouble shortens exactly representable values to half or single precision; the server's Lua
    // decoder is not promised those, so every double goes out as a 64-bit float (initial byte 0xFB, big-endian).
    private static void WriteFloat64(CborWriter writer, double value)
    {
        Span<byte> encoded = stackalloc byte[9];
        encoded[0] = 0xFB;
        System.Buffers.Binary.BinaryPrimitives.WriteDoubleBigEndian(encoded[1..], value);
        writer.WriteEncodedValue(encoded);
    }

    private static void WriteArray(CborWriter writer, IReadOnlyList<object?> items)
    {
        writer.WriteStartArray(items.Count);
        foreach (var item in items)
        {
            WriteValue(writer, item);
        }

        writer.WriteEndArray();
    }

    private static object? ReadValue(CborReader reader)
    {
        switch (reader.PeekState())
        {
            case CborReaderState.UnsignedInteger:
            case CborReaderState.NegativeInteger:
                return reader.ReadInt64();
            case CborReaderState.HalfPrecisionFloat:
            case CborReaderState.SinglePrecisionFloat:
            case CborReaderState.DoublePrecisionFloat:
                return reader.ReadDouble();
            case CborReaderState.TextString:
                var text = reader.ReadTextString();
                return text == RemoteApiWords.Nil ? null : text;
            case CborReaderState.ByteString:
                return reader.ReadByteString();
            case CborReaderState.Boolean:
                return reader.ReadBoolean();
            case CborReaderState.Null:
            case CborReaderState.SimpleValue:
                reader.SkipValue();
                return null;
            case CborReaderState.Tag:
                reader.ReadTag();
                return ReadValue(reader);
            case CborReaderState.StartArray:
                reader.ReadStartArray();
                var list = new List<object?>();
                while (reader.PeekState() != CborReaderState.EndArray)
                {
                    list.Add(ReadValue(reader));
                }

                reader.ReadEndArray();
                return list;
            case CborReaderState.StartMap:
                reader.ReadStartMap();
                var map = new Dictionary<string, object?>(StringComparer.Ordinal);
                while (reader.PeekState() != CborReaderState.EndMap)
                {
                    var key = ReadValue(reader);
                    map[Convert.ToString(key, System.Globalization.CultureInfo.InvariantCulture) ?? RemoteApiWords.Nil] = ReadValue(reader);
                }

                reader.ReadEndMap();
                return map;
            default:
                throw new FormatException($"unexpected CBOR item {reader.PeekState()}");
        }
    }
}
