using System.Buffers.Binary;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Bus.Client;

/// <summary>
/// The host end of the module bus: Dynamixel-2.0 requests with timeouts and retries, sync write / sync read for the
/// per-cycle exchange, broadcast discovery and per-module statistics. Time comes from the given
/// <see cref="TimeProvider"/>. After construction no request allocates. One thread uses a client at a time.
/// <para>
/// A late reply is never taken for a new one. Before each request the bytes already received are drained and every
/// status frame among them is counted as late (<see cref="LateReplies"/>, per module in
/// <see cref="ModuleStatistics.LateReplies"/>), apart from real CRC errors. While waiting, a reply is taken only from
/// the module asked and only with the length the request calls for (or an error status); any other status frame is
/// counted as late and the wait goes on. Each transaction's timeout is its wire time (request and reply) plus
/// <see cref="BusClientOptions.ResponseMargin"/>, the module turnaround and scheduling margin. After a reply has timed
/// out, the next request waits one more margin first, draining: a reply that is only a little late (the common case
/// on a loaded host) is then counted as late instead of arriving inside the next request's window, where a reply of
/// the same module and length could not be told from the right one (status packets carry no request number).
/// </para>
/// </summary>
public sealed partial class BusClient : IDisposable
{
    private const int MaxId = 252;
    private readonly IByteLink _link;
    private readonly TimeProvider _time;
    private readonly BusClientOptions _options;
    private readonly FrameDecoder _decoder = new();
    private readonly FrameDecoder _lateDecoder = new();
    private readonly byte[] _tx = new byte[FrameConstants.MaxFrameSize * 2];
    private readonly byte[] _rx = new byte[512];
    private readonly byte[] _params = new byte[FrameConstants.MaxFrameSize];
    private readonly ModuleStatistics[] _stats = new ModuleStatistics[256];
    private int _rxCount;
    private int _rxUsed;
    private long _strayFrames;
    private long _lateReplies;
    private long _quietUntil;
    private long _wireFreeAt;
    private BusInterruption? _interruption;

    /// <summary>
    /// Creates a client on <paramref name="link"/> (owned and disposed by the client), timing on the link's own clock
    /// when it has one (<see cref="IClockedLink"/>, the virtual bus) and on the system clock otherwise.
    /// </summary>
    public BusClient(IByteLink link, BusClientOptions? options = null)
        : this(link, (link as IClockedLink)?.Clock ?? TimeProvider.System, options)
    {
    }

    /// <summary>Creates a client on <paramref name="link"/> (the client owns and disposes it).</summary>
    public BusClient(IByteLink link, TimeProvider time, BusClientOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(link);
        ArgumentNullException.ThrowIfNull(time);
        _link = link;
        _time = time;
        _options = options ?? new BusClientOptions();
        for (var i = 0; i < _stats.Length; i++)
        {
            _stats[i] = new ModuleStatistics((byte)i, time.TimestampFrequency);
        }

        ByteTime = TimeSpan.FromTicks(Math.Max(1, 10 * TimeSpan.TicksPerSecond / link.BaudRate));
    }

    /// <summary>
    /// While set and raised, the next frame is not sent: <see cref="BusWorkInterruptedException"/> is thrown instead
    /// (set by the bus's owner around work that may be cut short; null: nothing interrupts).
    /// </summary>
    public BusInterruption? Interruption
    {
        get => Volatile.Read(ref _interruption);
        set => Volatile.Write(ref _interruption, value);
    }

    /// <summary>The link the client talks through.</summary>
    public IByteLink Link => _link;

    /// <summary>The clock timeouts and latencies are measured on.</summary>
    public TimeProvider Time => _time;

    /// <summary>Wire time of one byte (start, 8 data, stop bits).</summary>
    public TimeSpan ByteTime { get; }

    /// <summary>Frames dropped by the decoder because of a bad CRC (all modules).</summary>
    public long CrcErrors => _decoder.CrcErrors;

    /// <summary>Bytes received that were part of no frame (noise, or two modules answering at once).</summary>
    public long DiscardedBytes => _decoder.DiscardedBytes;

    /// <summary>Valid frames that are not status replies (nobody asked for them).</summary>
    public long StrayFrames => _strayFrames;

    /// <summary>
    /// Status frames that arrived after their request had been given up on, or that answered another request than
    /// the one waited for (all modules). None of them was taken as a reply.
    /// </summary>
    public long LateReplies => Volatile.Read(ref _lateReplies);

    /// <summary>Counters of one module.</summary>
    public ModuleStatistics Statistics(byte id) => _stats[id];

    /// <summary>The counters of the modules <paramref name="ids"/>, summed.</summary>
    public BusTotals Totals(IEnumerable<byte> ids)
    {
        ArgumentNullException.ThrowIfNull(ids);
        long frames = 0, crc = 0, timeouts = 0, retries = 0;
        foreach (var id in ids)
        {
            var s = _stats[id];
            frames += s.FramesSent + s.FramesReceived;
            crc += s.CrcErrors;
            timeouts += s.Timeouts;
            retries += s.Retries;
        }

        return new BusTotals(frames, crc, timeouts, retries);
    }

    /// <summary>Pings one module.</summary>
    public Reply Ping(byte id, out PingInfo info)
    {
        info = default;
        var reply = Transact(id, Instruction.Ping, ReadOnlySpan<byte>.Empty, 3);
        if (reply.Outcome == ReplyOutcome.Ok)
        {
            var p = _decoder.Parameters;
            info = new PingInfo(id, BinaryPrimitives.ReadUInt16LittleEndian(p), p[2]);
        }

        return reply;
    }

    /// <summary>
    /// Broadcast ping: every module answers; returns how many answered (up to <paramref name="found"/>'s length), in
    /// the order they answered. Listens until no answer came for <see cref="BusClientOptions.DiscoveryWindow"/>.
    /// </summary>
    public int Discover(Span<PingInfo> found)
    {
        Send(FrameConstants.BroadcastId, Instruction.Ping, ReadOnlySpan<byte>.Empty);
        var count = 0;
        var deadline = _time.GetTimestamp() + Ticks(_options.DiscoveryWindow);
        while (NextFrame(deadline))
        {
            if (_decoder.IsStatus && _decoder.Parameters.Length >= 3 && count < found.Length)
            {
                var p = _decoder.Parameters;
                found[count++] = new PingInfo(_decoder.Id, BinaryPrimitives.ReadUInt16LittleEndian(p), p[2]);
                _stats[_decoder.Id].Received(0);
                deadline = _time.GetTimestamp() + Ticks(_options.DiscoveryWindow);
            }
        }

        return count;
    }

    /// <summary>Reads <paramref name="data"/>.Length bytes from <paramref name="address"/> of module <paramref name="id"/>.</summary>
    public Reply Read(byte id, ushort address, Span<byte> data) => Read(id, address, data, _options.Retries);

    /// <summary>
    /// Reads the block <paramref name="start"/>..start + <paramref name="block"/>.Length of module <paramref name="id"/>
    /// one mapped run (<see cref="ControlTable.MappedRuns"/>) at a time, since a read over unmapped bytes is refused;
    /// unmapped bytes of <paramref name="block"/> are set to 0. Returns the first reply that did not succeed, or the last.
    /// </summary>
    public Reply ReadMapped(byte id, ControlTable table, int start, Span<byte> block) => ReadMapped(id, table, start, block, _options.Retries);

    /// <summary>As <see cref="ReadMapped(byte, ControlTable, int, Span{byte})"/>, each run's read retried <paramref name="retries"/> times (set-up that must get through insists).</summary>
    /// <param name="id">The module.</param>
    /// <param name="table">The control table (its mapped runs).</param>
    /// <param name="start">First address of the block.</param>
    /// <param name="block">Receives the block.</param>
    /// <param name="retries">Retries of each run's read.</param>
    public Reply ReadMapped(byte id, ControlTable table, int start, Span<byte> block, int retries)
    {
        ArgumentNullException.ThrowIfNull(table);
        block.Clear();
        var reply = new Reply(ReplyOutcome.Ok, 0);
        foreach (var (address, length) in table.MappedRuns(start, start + block.Length))
        {
            reply = Read(id, (ushort)address, block.Slice(address - start, length), retries);
            if (!reply.Succeeded)
            {
                return reply;
            }
        }

        return reply;
    }

    /// <summary>Writes <paramref name="data"/> at <paramref name="address"/> of module <paramref name="id"/> and waits for the acknowledgement.</summary>
    public Reply Write(byte id, ushort address, ReadOnlySpan<byte> data) => WriteAt(Instruction.Write, id, address, data, _options.Retries);

    /// <summary>Restarts a module (it answers before restarting).</summary>
    public Reply Reboot(byte id) => Transact(id, Instruction.Reboot, ReadOnlySpan<byte>.Empty, 0);

    /// <summary>Restores a module's factory parameters (<paramref name="option"/>: 0xFF all, 0x01 all but ID, 0x02 all but ID and baud).</summary>
    public Reply FactoryReset(byte id, byte option = 0x02) => Transact(id, Instruction.FactoryReset, [option], 0);

    /// <summary>
    /// Sync write: the same <paramref name="length"/> bytes at <paramref name="address"/> of every module in
    /// <paramref name="ids"/>, their data back to back in <paramref name="data"/>. No module replies.
    /// </summary>
    public void SyncWrite(ushort address, int length, ReadOnlySpan<byte> ids, ReadOnlySpan<byte> data)
    {
        if (data.Length != ids.Length * length)
        {
            throw new ArgumentException($"sync write needs {ids.Length * length} data bytes, got {data.Length}", nameof(data));
        }

        var p = _params.AsSpan(0, 4 + ids.Length * (1 + length));
        BinaryPrimitives.WriteUInt16LittleEndian(p, address);
        BinaryPrimitives.WriteUInt16LittleEndian(p[2..], (ushort)length);
        var o = 4;
        for (var i = 0; i < ids.Length; i++)
        {
            p[o++] = ids[i];
            data.Slice(i * length, length).CopyTo(p[o..]);
            o += length;
            _stats[ids[i]].Sent();
        }

        Send(FrameConstants.BroadcastId, Instruction.SyncWrite, p, countStatistics: false);
    }

    /// <summary>
    /// Sync read of <paramref name="length"/> bytes at <paramref name="address"/> from every module in
    /// <paramref name="ids"/> into <paramref name="data"/> (back to back). A module that does not answer, or answers
    /// corrupted, is asked again on its own (up to the retry budget). <paramref name="replies"/> receives each
    /// module's outcome. Returns how many modules answered.
    /// </summary>
    public int SyncRead(ushort address, int length, ReadOnlySpan<byte> ids, Span<byte> data, Span<Reply> replies)
    {
        if (data.Length < ids.Length * length || replies.Length < ids.Length)
        {
            throw new ArgumentException("sync read buffers are too small for the modules listed");
        }

        var p = _params.AsSpan(0, 4 + ids.Length);
        BinaryPrimitives.WriteUInt16LittleEndian(p, address);
        BinaryPrimitives.WriteUInt16LittleEndian(p[2..], (ushort)length);
        ids.CopyTo(p[4..]);
        for (var i = 0; i < ids.Length; i++)
        {
            replies[i] = Reply.TimedOut;
            _stats[ids[i]].Sent();
        }

        var requestBytes = FrameConstants.Overhead + 4 + ids.Length;
        var replyBytes = FrameConstants.Overhead + 1 + length;
        var sentAt = Send(FrameConstants.BroadcastId, Instruction.SyncRead, p, countStatistics: false);
        // Modules answer in turn; allow each reply its worst-case stuffing (a third of the data) and a small gap.
        var deadline = sentAt + Ticks(WireTime(requestBytes + (ids.Length * (replyBytes + (length / 3) + 2)))) + (ids.Length * Ticks(_options.ResponseMargin));
        var answered = 0;
        while (answered < ids.Length && NextFrame(deadline))
        {
            var index = ids.IndexOf(_decoder.Id);
            if (!_decoder.IsStatus)
            {
                _strayFrames++;
                continue;
            }

            if (index < 0 || replies[index].Outcome == ReplyOutcome.Ok || (_decoder.Parameters.Length != length && (_decoder.Error & 0x7F) == 0))
            {
                Late(_decoder.Id);
                continue;
            }

            var stats = _stats[_decoder.Id];
            stats.Received(_time.GetTimestamp() - sentAt);
            if (_decoder.Error != 0)
            {
                stats.ErrorReply();
            }

            if (_decoder.Parameters.Length != length)
            {
                replies[index] = new Reply(ReplyOutcome.BadLength, _decoder.Error); // an error status without data (firmware before issue 29)
                continue;
            }

            // A refusal carries the length asked of zeros (as ROBOTIS devices answer): a final answer, as Read's.
            _decoder.Parameters.CopyTo(data.Slice(index * length, length));
            replies[index] = new Reply(ReplyOutcome.Ok, _decoder.Error);
            answered++;
        }

        // Ask the missing ones individually.
        if (answered < ids.Length)
        {
            QuietAfterTimeout();
        }

        for (var i = 0; i < ids.Length && answered < ids.Length; i++)
        {
            if (replies[i].Outcome == ReplyOutcome.Ok)
            {
                continue;
            }

            _stats[ids[i]].Timeout();
            _stats[ids[i]].Retry();
            replies[i] = Read(ids[i], address, data.Slice(i * length, length));
            if (replies[i].Outcome == ReplyOutcome.Ok)
            {
                answered++;
            }
        }

        return answered;
    }

    /// <summary>Wire time of <paramref name="bytes"/> bytes at the link's baud.</summary>
    public TimeSpan WireTime(int bytes) => TimeSpan.FromTicks(ByteTime.Ticks * bytes);

    /// <inheritdoc />
    public void Dispose() => _link.Dispose();

    private Reply Transact(byte id, Instruction instruction, ReadOnlySpan<byte> parameters, int replyParameterCount) =>
        Transact(id, instruction, parameters, replyParameterCount, _options.Retries);

    private Reply Transact(byte id, Instruction instruction, ReadOnlySpan<byte> parameters, int replyParameterCount, int retries)
    {
        var stats = _stats[id];
        var requestBytes = FrameConstants.Overhead + parameters.Length;
        var replyBytes = FrameConstants.Overhead + 1 + replyParameterCount;
        for (var attempt = 0; ; attempt++)
        {
            var crcBefore = _decoder.CrcErrors;
            var sentAt = Send(id, instruction, parameters);
            var deadline = sentAt + Ticks(WireTime(requestBytes + replyBytes) + _options.ResponseMargin);
            var wrongLength = false;
            while (NextFrame(deadline))
            {
                if (!_decoder.IsStatus)
                {
                    _strayFrames++;
                    continue;
                }

                // Dynamixel 2.0 status packets carry no request number: the reply to this request is the one from
                // this module with this request's reply length (or an error status, which has no data).
                if (_decoder.Id != id || (_decoder.Parameters.Length != replyParameterCount && (_decoder.Error & 0x7F) == 0))
                {
                    wrongLength |= _decoder.Id == id;
                    Late(_decoder.Id);
                    continue;
                }

                stats.Received(_time.GetTimestamp() - sentAt);
                if (_decoder.Error != 0)
                {
                    stats.ErrorReply();
                }

                return new Reply(ReplyOutcome.Ok, _decoder.Error);
            }

            if (wrongLength && attempt >= retries)
            {
                stats.Timeout();
                return new Reply(ReplyOutcome.BadLength, 0); // the module answered, but never with this request's length
            }

            if (_decoder.CrcErrors != crcBefore)
            {
                stats.CrcError();
            }

            QuietAfterTimeout();
            stats.Timeout();
            if (attempt >= retries)
            {
                return Reply.TimedOut;
            }

            stats.Retry();
        }
    }

    /// <summary>Sends a frame; returns the timestamp at which it starts on the wire.</summary>
    private long Send(byte id, Instruction instruction, ReadOnlySpan<byte> parameters, bool countStatistics = true)
    {
        // Anything received before the request answers an earlier one: drain it (counting the late replies in it)
        // so that it cannot be taken for the answer to this request.
        if (_interruption is { IsRaised: true } interruption)
        {
            throw new BusWorkInterruptedException(interruption.Reason ?? "interrupted");
        }

        DrainLate();
        var n = FrameEncoder.EncodeInstruction(_tx, id, instruction, parameters);

        // A write returns once the bytes are queued; the frame starts on the wire when the ones before it are out,
        // and reply deadlines count from there.
        var now = Math.Max(_time.GetTimestamp(), _wireFreeAt);
        _wireFreeAt = now + Ticks(WireTime(n));
        _link.Write(_tx.AsSpan(0, n));
        if (countStatistics && id != FrameConstants.BroadcastId)
        {
            _stats[id].Sent();
        }

        return now;
    }

    /// <summary>
    /// Takes every byte received so far (buffered here, or waiting in the link) without waiting, and counts the status
    /// frames among them as late replies. The main decoder starts the next request clean; a partial frame left over
    /// is dropped (its CRC is never checked, so it is not counted as a CRC error).
    /// </summary>
    private void DrainLate()
    {
        _lateDecoder.Reset();
        CountLate(_rx.AsSpan(_rxUsed, _rxCount - _rxUsed));
        int n;
        while ((n = _link.Read(_rx, TimeSpan.Zero)) > 0)
        {
            CountLate(_rx.AsSpan(0, n));
        }

        for (var wait = _quietUntil - _time.GetTimestamp(); wait > 0; wait = _quietUntil - _time.GetTimestamp())
        {
            n = _link.Read(_rx, TimeSpan.FromTicks(wait * TimeSpan.TicksPerSecond / _time.TimestampFrequency));
            CountLate(_rx.AsSpan(0, n));
        }

        _quietUntil = 0;

        _decoder.Reset();
        _rxCount = _rxUsed = 0;
    }

    private void CountLate(ReadOnlySpan<byte> bytes)
    {
        while (!bytes.IsEmpty)
        {
            if (!_lateDecoder.Push(bytes, out var used))
            {
                return;
            }

            bytes = bytes[used..];
            if (_lateDecoder.IsStatus)
            {
                Late(_lateDecoder.Id);
            }
            else
            {
                _strayFrames++;
            }
        }
    }

    /// <summary>A reply timed out: it may still come, so the next request first waits one more margin, draining.</summary>
    private void QuietAfterTimeout() => _quietUntil = _time.GetTimestamp() + Ticks(_options.ResponseMargin);

    private void Late(byte id)
    {
        Interlocked.Increment(ref _lateReplies);
        _stats[id].LateReply();
    }

    /// <summary>Reads until the decoder yields a frame or the deadline (a timestamp) passes.</summary>
    private bool NextFrame(long deadline)
    {
        while (true)
        {
            if (_decoder.Push(_rx.AsSpan(_rxUsed, _rxCount - _rxUsed), out var used))
            {
                _rxUsed += used;
                return true;
            }

            _rxUsed = _rxCount = 0;
            var remaining = deadline - _time.GetTimestamp();
            if (remaining <= 0)
            {
                return false;
            }

            _rxCount = _link.Read(_rx, TimeSpan.FromTicks(remaining * TimeSpan.TicksPerSecond / _time.TimestampFrequency));
        }
    }

    private long Ticks(TimeSpan span) => span.Ticks * _time.TimestampFrequency / TimeSpan.TicksPerSecond;
}
