using System.Buffers.Binary;

namespace RobotControl.Bus.Protocol;

/// <summary>
/// Streaming Dynamixel 2.0 frame decoder: finds headers in a byte stream, checks length and CRC, removes byte
/// stuffing. A frame with a bad CRC is counted and dropped (never delivered), and the decoder resynchronises on the
/// next header inside the bytes it already holds. Allocation-free after construction; not thread-safe.
/// </summary>
public sealed class FrameDecoder
{
    private readonly byte[] _buffer = new byte[FrameConstants.MaxFrameSize];
    private readonly byte[] _payload = new byte[FrameConstants.MaxFrameSize];
    private int _count;
    private int _consumed;
    private int _payloadLength;

    /// <summary>ID of the frame last delivered.</summary>
    public byte Id { get; private set; }

    /// <summary>Instruction byte of the frame last delivered (0x55 for status).</summary>
    public byte Instruction { get; private set; }

    /// <summary>Error byte of the status frame last delivered (0 for an instruction frame).</summary>
    public byte Error { get; private set; }

    /// <summary>True when the frame last delivered is a status packet.</summary>
    public bool IsStatus => Instruction == (byte)Protocol.Instruction.Status;

    /// <summary>Unstuffed parameters of the frame last delivered (after the error byte for a status packet).</summary>
    public ReadOnlySpan<byte> Parameters => _payload.AsSpan(0, _payloadLength);

    /// <summary>Length of the frame last delivered on the wire (stuffed, with header and CRC).</summary>
    public int FrameLength { get; private set; }

    /// <summary>Frames dropped because their CRC did not match.</summary>
    public long CrcErrors { get; private set; }

    /// <summary>Headers dropped because their length field was impossible.</summary>
    public long FramingErrors { get; private set; }

    /// <summary>Bytes discarded while looking for a header.</summary>
    public long DiscardedBytes { get; private set; }

    /// <summary>Number of bytes held toward an incomplete frame.</summary>
    public int Pending => _count - _consumed;

    /// <summary>Forgets any partial frame (e.g. after a timeout).</summary>
    public void Reset()
    {
        DiscardedBytes += _count - _consumed;
        _count = 0;
        _consumed = 0;
    }

    /// <summary>
    /// Feeds bytes until one frame completes. Returns true when a valid frame is available through <see cref="Id"/>,
    /// <see cref="Instruction"/>, <see cref="Error"/> and <see cref="Parameters"/> (valid until the next call);
    /// <paramref name="used"/> tells how many input bytes were taken. Call again with the rest (or an empty span:
    /// bytes held from a dropped frame may already hold the next one).
    /// </summary>
    public bool Push(ReadOnlySpan<byte> data, out int used)
    {
        if (_consumed > 0)
        {
            Compact(_consumed);
            _consumed = 0;
        }

        used = 0;
        while (true)
        {
            if (TryParse())
            {
                return true;
            }

            if (used >= data.Length)
            {
                return false;
            }

            // Take as many bytes as the frame in progress can still need (at least one).
            var want = Needed();
            var take = Math.Min(Math.Min(want, data.Length - used), _buffer.Length - _count);
            data.Slice(used, take).CopyTo(_buffer.AsSpan(_count));
            _count += take;
            used += take;
        }
    }

    private int Needed()
    {
        if (_count < 7)
        {
            return _count < 4 ? 1 : 7 - _count;
        }

        var total = 7 + BinaryPrimitives.ReadUInt16LittleEndian(_buffer.AsSpan(5, 2));
        return Math.Max(1, total - _count);
    }

    private bool TryParse()
    {
        while (_count > 0)
        {
            // Header prefix FF FF FD 00.
            var prefix = Math.Min(_count, 4);
            if (!IsHeaderPrefix(_buffer.AsSpan(0, prefix)))
            {
                DropToNextHeader(1);
                continue;
            }

            if (_count < 7)
            {
                return false;
            }

            var length = BinaryPrimitives.ReadUInt16LittleEndian(_buffer.AsSpan(5, 2));
            if (length < 3 || 7 + length > _buffer.Length)
            {
                FramingErrors++;
                DropToNextHeader(1);
                continue;
            }

            var total = 7 + length;
            if (_count < total)
            {
                return false;
            }

            var expected = BinaryPrimitives.ReadUInt16LittleEndian(_buffer.AsSpan(total - 2, 2));
            if (Crc16.Compute(_buffer.AsSpan(0, total - 2)) != expected || !Unstuff(total))
            {
                CrcErrors++;
                DropToNextHeader(1);
                continue;
            }

            FrameLength = total;
            _consumed = total;
            return true;
        }

        return false;
    }

    private bool Unstuff(int total)
    {
        Id = _buffer[4];
        var region = _buffer.AsSpan(7, total - 9);
        var n = 0;
        var run = 0;
        for (var i = 0; i < region.Length; i++)
        {
            var b = region[i];
            if (run == 3)
            {
                // FF FF FD inside the body must be followed by the stuffing FD; anything else is not a valid frame.
                if (b != 0xFD)
                {
                    return false;
                }

                run = 0;
                continue;
            }

            _payload[n++] = b;
            run = StuffState.Next(run, b);
        }

        if (n < 1 || run == 3)
        {
            return false;
        }

        Instruction = _payload[0];
        var skip = 1;
        Error = 0;
        if (Instruction == (byte)Protocol.Instruction.Status)
        {
            if (n < 2)
            {
                return false;
            }

            Error = _payload[1];
            skip = 2;
        }

        _payloadLength = n - skip;
        _payload.AsSpan(skip, _payloadLength).CopyTo(_payload);
        return true;
    }

    private static bool IsHeaderPrefix(ReadOnlySpan<byte> s)
    {
        ReadOnlySpan<byte> header = [0xFF, 0xFF, 0xFD, 0x00];
        return s.SequenceEqual(header[..s.Length]);
    }

    private void DropToNextHeader(int from)
    {
        var i = from;
        for (; i < _count; i++)
        {
            if (IsHeaderPrefix(_buffer.AsSpan(i, Math.Min(4, _count - i))))
            {
                break;
            }
        }

        DiscardedBytes += i;
        Compact(i);
    }

    private void Compact(int n)
    {
        _buffer.AsSpan(n, _count - n).CopyTo(_buffer);
        _count -= n;
    }
}
