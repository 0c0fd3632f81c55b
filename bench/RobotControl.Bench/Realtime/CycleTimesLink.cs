using System.Diagnostics;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;

namespace RobotControl.Bench.Realtime;

/// <summary>
/// Wraps the host's bus link and timestamps (<see cref="Stopwatch"/>) every goal SYNC WRITE, the first frame of each
/// bus cycle, into a preallocated array: the bus cycle period distribution of a wall-clock run. Allocates nothing.
/// <paramref name="atWarmCycle"/> runs once, at cycle <see cref="WarmCycle"/> (the start of the allocation window).
/// </summary>
internal sealed class CycleTimesLink(IByteLink inner, int capacity, Action atWarmCycle) : IByteLink
{
    private readonly long[] _starts = new long[capacity];
    private int _count;

    /// <summary>The cycle from which the run counts as warm (2 s at 1 kHz).</summary>
    public const int WarmCycle = 2_000;

    public string Description => inner.Description;

    public int BaudRate => inner.BaudRate;

    /// <summary>Cycle start timestamps recorded so far.</summary>
    public ReadOnlySpan<long> Starts => _starts.AsSpan(0, Volatile.Read(ref _count));

    public void Write(ReadOnlySpan<byte> data)
    {
        // FF FF FD 00, ID 0xFE (broadcast), LEN (2), instruction
        if (data.Length > 7 && data[4] == FrameConstants.BroadcastId && data[7] == (byte)Instruction.SyncWrite && _count < _starts.Length)
        {
            _starts[_count] = Stopwatch.GetTimestamp();
            Volatile.Write(ref _count, _count + 1);
            if (_count == WarmCycle)
            {
                atWarmCycle();
            }
        }

        inner.Write(data);
    }

    public int Read(Span<byte> buffer, TimeSpan timeout) => inner.Read(buffer, timeout);

    public void DiscardInput() => inner.DiscardInput();

    public void Dispose() => inner.Dispose();
}
