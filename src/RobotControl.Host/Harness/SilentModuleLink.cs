using RobotControl.Bus.Transports;

namespace RobotControl.Host.Harness;

/// <summary>
/// The host's end of a virtual bus on which modules go silent at given times (<c>--inject silent=</c>): from then on
/// their replies never reach the host (a broken transmit line), while they still hear the host. The virtual link
/// hands over whole reply frames, so frames are dropped whole by their ID.
/// </summary>
internal sealed class SilentModuleLink : IByteLink
{
    private const int HeaderLength = 7; // FF FF FD 00, ID, length (2)
    private readonly IByteLink _inner;
    private readonly TimeProvider _clock;
    private readonly List<(byte Id, long At)> _silent = [];
    private readonly byte[] _scratch = new byte[4096];

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
    public void Write(ReadOnlySpan<byte> data) => _inner.Write(data);

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
            if (!(length > 4 && Silenced(frame[4], now)))
            {
                frame[..length].CopyTo(destination[kept..]);
                kept += length;
            }

            at += length;
        }

        return kept;
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
