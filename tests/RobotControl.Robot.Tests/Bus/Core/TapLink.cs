using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Simulation.Time;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>
/// A wire between the host and the virtual bus that a test watches and breaks: every frame the host sends is recorded
/// (with the clock's time), chosen host frames never reach the modules (<see cref="Lose"/>), replies can be lost
/// (<see cref="Deaf"/>, <see cref="LoseReply"/>) or changed (<see cref="Rewrite"/>, re-encoded with a valid CRC), and
/// writes can fail as an unplugged adapter's do (<see cref="Failing"/>). The modules themselves are the real firmware.
/// </summary>
internal sealed class TapLink(IByteLink inner) : IByteLink
{
    private readonly ManualTimeProvider _clock = (ManualTimeProvider)((IClockedLink)inner).Clock;
    private readonly FrameDecoder _hostFrames = new();
    private readonly FrameDecoder _replyFrame = new();
    private readonly List<HostFrame> _sent = [];
    private HostFrame? _lastRequest;
    private int _failedWrites;
    private bool _deaf;
    private bool _failing;

    /// <summary>Host frames the modules never hear (as if lost on the wire); null: none.</summary>
    public Func<HostFrame, bool>? Lose { get; set; }

    /// <summary>Replies lost on the way back, given the request they answer and the replying module; null: none.</summary>
    public Func<HostFrame?, byte, bool>? LoseReply { get; set; }

    /// <summary>Another reply in place of one (given the request it answers), or null to leave it alone.</summary>
    public Func<HostFrame?, ReplyFrame, ReplyFrame?>? Rewrite { get; set; }

    /// <summary>While true, every reply is lost.</summary>
    public bool Deaf
    {
        get => Volatile.Read(ref _deaf);
        set => Volatile.Write(ref _deaf, value);
    }

    /// <summary>
    /// While true, every write fails with an <see cref="IOException"/>, the bus clock moving <see cref="FailureTime"/>
    /// each time, and a read gets nothing once its timeout has passed (the virtual bus is not run meanwhile).
    /// </summary>
    public bool Failing
    {
        get => Volatile.Read(ref _failing);
        set => Volatile.Write(ref _failing, value);
    }

    /// <summary>Bus time a failed write takes (the manual clock is moved by it).</summary>
    public TimeSpan FailureTime { get; set; } = TimeSpan.FromMilliseconds(10);

    public int FailedWrites => Volatile.Read(ref _failedWrites);

    public bool Disposed { get; private set; }

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    /// <summary>Every frame the host sent so far (lost ones included), oldest first.</summary>
    public IReadOnlyList<HostFrame> Sent
    {
        get
        {
            lock (_sent)
            {
                return [.. _sent];
            }
        }
    }

    /// <summary>
    /// Cuts modules <paramref name="ids"/> off the wire: frames addressed to them alone never reach them and their
    /// replies are lost (they still hear broadcasts and sync writes, as a module with a broken transmit line does).
    /// </summary>
    public void Mute(params byte[] ids)
    {
        Lose = f => ids.Contains(f.Id);
        LoseReply = (_, id) => ids.Contains(id);
    }

    /// <summary>Puts every module back on the wire.</summary>
    public void Unmute()
    {
        Lose = null;
        LoseReply = null;
    }

    /// <summary>Forgets the frames recorded so far.</summary>
    public void ClearSent()
    {
        lock (_sent)
        {
            _sent.Clear();
        }
    }

    public void Write(ReadOnlySpan<byte> data)
    {
        if (Failing)
        {
            Interlocked.Increment(ref _failedWrites);
            _clock.Advance(FailureTime);
            throw new IOException("the test unplugged the adapter");
        }

        var at = _clock.GetTimestamp();
        var lost = false;
        var rest = data;
        while (!rest.IsEmpty && _hostFrames.Push(rest, out var used))
        {
            rest = rest[used..];
            var frame = new HostFrame(_hostFrames.Id, (Instruction)_hostFrames.Instruction, _hostFrames.Parameters.ToArray(), at);
            lock (_sent)
            {
                _sent.Add(frame);
            }

            _lastRequest = frame;
            lost |= Lose?.Invoke(frame) == true;
        }

        if (!lost)
        {
            inner.Write(data);
        }
    }

    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        if (Failing)
        {
            _clock.Advance(timeout); // nothing comes in; the virtual bus is left alone (its clock may be far ahead)
            return 0;
        }

        var got = new byte[buffer.Length];
        var n = inner.Read(got, timeout);
        if (n == 0 || (!Deaf && LoseReply is null && Rewrite is null))
        {
            got.AsSpan(0, n).CopyTo(buffer);
            return n;
        }

        if (Deaf)
        {
            return 0;
        }

        // The virtual bus hands over whole frames; anything else passes unchanged.
        var output = new List<byte>();
        var bytes = got.AsSpan(0, n);
        while (!bytes.IsEmpty)
        {
            var length = bytes.Length >= 7 && bytes[0] == 0xFF && bytes[1] == 0xFF && bytes[2] == 0xFD && bytes[3] == 0
                ? 7 + BinaryPrimitives.ReadUInt16LittleEndian(bytes[5..])
                : 0;
            if (length == 0 || length > bytes.Length)
            {
                output.AddRange(bytes.ToArray());
                break;
            }

            var raw = bytes[..length];
            bytes = bytes[length..];
            _replyFrame.Reset();
            if (!_replyFrame.Push(raw, out _) || !_replyFrame.IsStatus)
            {
                output.AddRange(raw.ToArray());
                continue;
            }

            var reply = new ReplyFrame(_replyFrame.Id, _replyFrame.Error, _replyFrame.Parameters.ToArray());
            var request = _lastRequest;
            if (LoseReply?.Invoke(request, reply.Id) == true)
            {
                continue;
            }

            if (Rewrite?.Invoke(request, reply) is { } changed)
            {
                var encoded = new byte[FrameConstants.MaxFrameSize];
                var m = FrameEncoder.EncodeStatus(encoded, changed.Id, changed.Error, changed.Parameters);
                output.AddRange(encoded.AsSpan(0, m).ToArray());
                continue;
            }

            output.AddRange(raw.ToArray());
        }

        var count = Math.Min(output.Count, buffer.Length);
        output.CopyTo(0, got, 0, count);
        got.AsSpan(0, count).CopyTo(buffer);
        return count;
    }

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose()
    {
        Disposed = true;
        inner.Dispose();
    }
}

/// <summary>A frame the host sent: its module (0xFE: broadcast), instruction and parameters, and when.</summary>
internal sealed record HostFrame(byte Id, Instruction Instruction, byte[] Parameters, long Timestamp)
{
    /// <summary>The control-table address a read or write starts at (the first two parameters).</summary>
    public int Address => Parameters.Length >= 2 ? BinaryPrimitives.ReadUInt16LittleEndian(Parameters) : -1;

    /// <summary>True for a read of <paramref name="id"/> at <paramref name="address"/>.</summary>
    public bool IsRead(byte id, int address) => Instruction == Instruction.Read && Id == id && Address == address;

    /// <summary>True for a write to <paramref name="id"/> at <paramref name="address"/>.</summary>
    public bool IsWrite(byte id, int address) => Instruction == Instruction.Write && Id == id && Address == address;
}

/// <summary>A status frame from a module: its ID, error byte and parameters.</summary>
internal sealed record ReplyFrame(byte Id, byte Error, byte[] Parameters);
