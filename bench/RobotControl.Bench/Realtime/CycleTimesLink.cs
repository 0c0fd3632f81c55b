using System.Diagnostics;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Bench.Realtime;

/// <summary>
/// Wraps the host's bus link and timestamps (<see cref="Stopwatch"/>) every goal SYNC WRITE, the first frame of each
/// bus cycle, into a preallocated array: the bus cycle period distribution of a wall-clock run. It also keeps every
/// link call of the first <see cref="TraceCapacity"/> (start, end, what, bytes) so that a gap at start-up can be taken
/// apart: host not calling, or replies not coming. Allocates nothing.
/// <paramref name="atWarmCycle"/> runs once, at cycle <see cref="WarmCycle"/> (the start of the allocation window).
/// </summary>
internal sealed class CycleTimesLink(IByteLink inner, int capacity, Action atWarmCycle) : IByteLink
{
    /// <summary>Link calls traced from the first one on (about 5 s of a 1 Mbaud LB-1.0 run).</summary>
    public const int TraceCapacity = 100_000;

    private readonly long[] _starts = new long[capacity];
    private readonly LinkCall[] _trace = new LinkCall[TraceCapacity];
    private int _count;
    private int _traced;

    /// <summary>The cycle from which the run counts as warm (2 s at 1 kHz).</summary>
    public const int WarmCycle = 2_000;

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    /// <summary>Cycle start timestamps recorded so far.</summary>
    public ReadOnlySpan<long> Starts => _starts.AsSpan(0, Volatile.Read(ref _count));

    /// <summary>The link calls traced (the first <see cref="TraceCapacity"/>).</summary>
    public ReadOnlySpan<LinkCall> Trace => _trace.AsSpan(0, Volatile.Read(ref _traced));

    public void Write(ReadOnlySpan<byte> data)
    {
        var start = Stopwatch.GetTimestamp();
        // FF FF FD 00, ID 0xFE (broadcast), LEN (2), instruction
        if (data.Length > 7 && data[4] == FrameConstants.BroadcastId && data[7] == (byte)Instruction.SyncWrite && _count < _starts.Length)
        {
            _starts[_count] = start;
            Volatile.Write(ref _count, _count + 1);
            if (_count == WarmCycle)
            {
                atWarmCycle();
            }
        }

        inner.Write(data);
        Record(start, 'W', data.Length > 7 ? data[7] : (byte)0, data.Length > 4 ? data[4] : (byte)0, data.Length, 0);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        var start = Stopwatch.GetTimestamp();
        var n = inner.Read(buffer, timeout);
        Record(start, 'R', 0, 0, n, (int)(timeout.Ticks / 10));
        return n;
    }

    public void DiscardInput()
    {
        var start = Stopwatch.GetTimestamp();
        inner.DiscardInput();
        Record(start, 'D', 0, 0, 0, 0);
    }

    public void Dispose() => inner.Dispose();

    private void Record(long start, char kind, byte instruction, byte id, int bytes, int timeoutUs)
    {
        if (_traced < _trace.Length)
        {
            _trace[_traced] = new LinkCall(start, Stopwatch.GetTimestamp(), kind, instruction, id, bytes, timeoutUs);
            Volatile.Write(ref _traced, _traced + 1);
        }
    }
}

/// <summary>One call on the link: when it started and ended (<see cref="Stopwatch"/> timestamps), W(rite), R(ead) or D(iscard), the instruction and ID of a written frame, bytes written or read, a read's timeout.</summary>
internal readonly record struct LinkCall(long Start, long End, char Kind, byte Instruction, byte Id, int Bytes, int TimeoutUs);
