using RobotControl.Bus.Transports;

namespace RobotControl.Host.Harness;

/// <summary>
/// The host's end of a virtual bus on which modules go silent at given times (<c>--inject silent=</c>): from then on
/// their replies never reach the host (a broken transmit line), while they still hear the host. The virtual link
/// hands over whole reply frames, so frames are dropped whole by their ID. In the combined status packet of a FAST
/// SYNC/BULK READ a silent module's part never comes, and the modules after it, which wait for it, send nothing
/// either: the packet is cut where that part would start (the part lengths come from the host's request).
/// </summary>
public sealed class SilentModuleLink : IByteLink
{
    private const int HeaderLength = 7; // FF FF FD 00, ID, length (2)
    private readonly IByteLink _inner;
    private readonly TimeProvider _clock;
    private readonly List<(byte Id, long At)> _silent = [];
    private readonly byte[] _scratch = new byte[4096];
    private readonly List<(byte Id, int Length)> _fastParts = [];

    /// <summary>Wraps <paramref name="inner"/>, whose clock is <paramref name="clock"/>; nobody is silent yet.</summary>
    public SilentModuleLink(IByteLink inner, TimeProvider clock)
    {
        _inner = inner;
        _clock = clock;
    }

    /// <summary>Module <paramref name="id"/> falls silent at <paramref name="at"/> (a timestamp of the link's clock).</summary>
    public void Silence(byte id, long at) => _silent.Add((id, at));

    /// <inheritdoc />
    public string Description => _inner.Description;

    /// <inheritdoc />
    public int BaudRate => _inner.BaudRate;

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data)
    {
        RememberFastRead(data);
        _inner.Write(data);
    }

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        while (true)
        {
            var n = _inner.Read(_scratch.AsSpan(0, Math.Min(buffer.Length, _scratch.Length)), timeout);
            if (n == 0)
            {
                return 0;
            }

            var kept = Filter(_scratch.AsSpan(0, n), buffer);
            if (kept > 0)
            {
                return kept;
            }
        }
    }

    /// <inheritdoc />
    public void DiscardInput() => _inner.DiscardInput();

    /// <inheritdoc />
    public void Dispose() => _inner.Dispose();

    private int Filter(ReadOnlySpan<byte> received, Span<byte> destination)
    {
        var now = _clock.GetTimestamp();
        var kept = 0;
        var at = 0;
        while (at < received.Length)
        {
            var frame = received[at..];
            var length = frame.Length >= HeaderLength && frame[0] == 0xFF && frame[1] == 0xFF && frame[2] == 0xFD
                ? Math.Min(frame.Length, HeaderLength + frame[5] + (frame[6] << 8))
                : frame.Length; // not a frame start: pass the rest on as it is
            if (length > 8 && frame[4] == 0xFE && frame[7] == 0x55 && _fastParts.Count > 0)
            {
                var cut = FastPacketCut(frame[..length], now);
                frame[..cut].CopyTo(destination[kept..]);
                kept += cut;
            }
            else if (!(length > 4 && Silenced(frame[4], now)))
            {
                frame[..length].CopyTo(destination[kept..]);
                kept += length;
            }

            at += length;
        }

        return kept;
    }

    // The parts of the combined reply to the last FAST SYNC READ (0x8A: addr, length, IDs) or FAST BULK READ (0x9A: per
    // module ID, addr, length) the host sent; the few parameter bytes of these requests are taken as written (a stuffed
    // FF FF FD among them would only make a test's silence start one cycle later).
    private void RememberFastRead(ReadOnlySpan<byte> frame)
    {
        if (frame.Length < 10 || frame[0] != 0xFF || frame[1] != 0xFF || frame[2] != 0xFD || frame[4] != 0xFE)
        {
            return;
        }

        var parameters = frame[8..^2];
        if (frame[7] == 0x8A && parameters.Length >= 4)
        {
            _fastParts.Clear();
            var length = parameters[2] | (parameters[3] << 8);
            foreach (var id in parameters[4..])
            {
                _fastParts.Add((id, length));
            }
        }
        else if (frame[7] == 0x9A)
        {
            _fastParts.Clear();
            for (var k = 0; k + 5 <= parameters.Length; k += 5)
            {
                _fastParts.Add((parameters[k], parameters[k + 3] | (parameters[k + 4] << 8)));
            }
        }
    }

    // Where the combined packet ends on a wire with silent modules: at the start of the first silent module's part.
    private int FastPacketCut(ReadOnlySpan<byte> packet, long now)
    {
        var at = 8; // header 4, ID, LEN 2, instruction 0x55
        foreach (var (id, length) in _fastParts)
        {
            if (at >= packet.Length || Silenced(id, now))
            {
                return Math.Min(at, packet.Length);
            }

            at += 4 + length; // error, ID, data, CRC
        }

        return packet.Length;
    }

    private bool Silenced(byte id, long now)
    {
        foreach (var (silentId, from) in _silent)
        {
            if (silentId == id && now >= from)
            {
                return true;
            }
        }

        return false;
    }
}
