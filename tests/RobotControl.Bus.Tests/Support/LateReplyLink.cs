using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Bus.Tests.Support;

/// <summary>
/// A scripted bus on its own manual clock: each request is answered after the delay the script gives for it (the
/// n-th request gets <c>delaysUs[n]</c>; past the end of the script, 50 us), so a reply can be made to come after the
/// host has given up on it. Reads are answered with <see cref="Pattern"/> bytes of the address asked, writes with an
/// empty status. A read that waits advances the clock to the next byte's arrival or to its timeout.
/// </summary>
internal sealed class LateReplyLink(int baud, params long[] delaysUs) : IByteLink, IClockedLink
{
    private readonly ManualClock _clock = new();
    private readonly FrameDecoder _requests = new();
    private readonly List<(long AtTicks, byte[] Bytes)> _pending = [];
    private int _requestCount;

    public string Description => "scripted late-reply bus";

    public int BaudRate => baud;

    public TimeProvider Clock => _clock;

    /// <summary>Requests received, in order: (module ID, instruction).</summary>
    public List<(byte Id, Instruction Instruction)> Requests { get; } = [];

    /// <summary>The data a module returns for a read of <paramref name="length"/> bytes at <paramref name="address"/>.</summary>
    public static byte[] Pattern(ushort address, int length) => [.. Enumerable.Range(0, length).Select(i => (byte)(address + (7 * i)))];

    public void Write(ReadOnlySpan<byte> data)
    {
        var bytes = data;
        while (!bytes.IsEmpty && _requests.Push(bytes, out var used))
        {
            bytes = bytes[used..];
            Requests.Add((_requests.Id, (Instruction)_requests.Instruction));
            var delay = _requestCount < delaysUs.Length ? delaysUs[_requestCount] : 50;
            _requestCount++;
            var p = _requests.Parameters;
            byte[] reply = _requests.Instruction == (byte)Instruction.Read
                ? Pattern(BinaryPrimitives.ReadUInt16LittleEndian(p), BinaryPrimitives.ReadUInt16LittleEndian(p[2..]))
                : [];
            var frame = new byte[FrameConstants.MaxFrameSize];
            var n = FrameEncoder.EncodeStatus(frame, _requests.Id, 0, reply);
            _pending.Add((_clock.Ticks + (delay * TimeSpan.TicksPerMicrosecond), frame[..n]));
        }
    }

    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        _pending.Sort((a, b) => a.AtTicks.CompareTo(b.AtTicks));
        if (_pending.Count == 0 || _pending[0].AtTicks > _clock.Ticks + timeout.Ticks)
        {
            _clock.Ticks += timeout.Ticks;
            return 0;
        }

        var (at, bytes) = _pending[0];
        _pending.RemoveAt(0);
        _clock.Ticks = Math.Max(_clock.Ticks, at);
        bytes.CopyTo(buffer);
        return bytes.Length;
    }

    public void DiscardInput() => _pending.RemoveAll(p => p.AtTicks <= _clock.Ticks);

    /// <summary>Lets <paramref name="time"/> pass with nobody reading.</summary>
    public void Idle(TimeSpan time) => _clock.Ticks += time.Ticks;

    public void Dispose()
    {
    }

    private sealed class ManualClock : TimeProvider
    {
        public long Ticks { get; set; }

        public override long TimestampFrequency => TimeSpan.TicksPerSecond;

        public override long GetTimestamp() => Ticks;
    }
}
