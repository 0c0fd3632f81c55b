namespace RobotControl.Plugins.Link;

/// <summary>
/// A single-producer, single-consumer ring of fixed-length frames that never makes the producer (the control loop)
/// wait: when the consumer (the sender thread) is behind, the producer overwrites the oldest frame, and the consumer
/// counts what it missed. Each slot carries the index of the frame in it (a sequence lock per slot), so the consumer
/// never takes a frame the producer is rewriting. Allocation-free after construction.
/// </summary>
internal sealed class FrameRing
{
    private const long Writing = -1;
    private readonly byte[] _frames;
    private readonly long[] _stamps;
    private readonly int _capacity;
    private long _head; // frames written (producer)
    private long _tail; // frames taken or skipped (consumer)
    private long _dropped;
    private long _next; // the index the producer writes (between BeginWrite and EndWrite)

    /// <summary>A ring of <paramref name="capacity"/> frames of <paramref name="frameLength"/> bytes.</summary>
    public FrameRing(int frameLength, int capacity)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(frameLength, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 2);
        FrameLength = frameLength;
        _capacity = capacity;
        _frames = new byte[frameLength * capacity];
        _stamps = new long[capacity];
        Array.Fill(_stamps, Writing);
    }

    /// <summary>Bytes per frame.</summary>
    public int FrameLength { get; }

    /// <summary>
    /// Frames overwritten before the consumer took them: those it skipped, plus those overwritten since it last looked
    /// (so the count grows while the consumer is stuck). Any thread.
    /// </summary>
    public long Dropped => Volatile.Read(ref _dropped) + Math.Max(0, Volatile.Read(ref _head) - Volatile.Read(ref _tail) - _capacity);

    /// <summary>The slot of the next frame (producer); always granted, overwriting the oldest when the ring is full.</summary>
    public Span<byte> BeginWrite()
    {
        _next = Volatile.Read(ref _head);
        var slot = (int)(_next % _capacity);
        Interlocked.Exchange(ref _stamps[slot], Writing); // a full fence: the slot reads as busy before its bytes change
        return _frames.AsSpan(slot * FrameLength, FrameLength);
    }

    /// <summary>Publishes the frame begun by <see cref="BeginWrite"/> (producer).</summary>
    public void EndWrite()
    {
        Volatile.Write(ref _stamps[(int)(_next % _capacity)], _next);
        Volatile.Write(ref _head, _next + 1);
    }

    /// <summary>Copies the oldest frame still in the ring into <paramref name="frame"/> (consumer); false when there is none.</summary>
    public bool TryRead(Span<byte> frame)
    {
        var spin = default(SpinWait);
        while (true)
        {
            var head = Volatile.Read(ref _head);
            var tail = _tail;
            if (tail == head)
            {
                return false;
            }

            if (head - tail > _capacity)
            {
                Volatile.Write(ref _dropped, _dropped + (head - _capacity - tail));
                tail = head - _capacity;
                Volatile.Write(ref _tail, tail);
            }

            var slot = (int)(tail % _capacity);
            if (Volatile.Read(ref _stamps[slot]) == tail)
            {
                _frames.AsSpan(slot * FrameLength, FrameLength).CopyTo(frame);
                Interlocked.MemoryBarrier();
                if (Volatile.Read(ref _stamps[slot]) == tail)
                {
                    Volatile.Write(ref _tail, tail + 1);
                    return true;
                }
            }

            spin.SpinOnce(); // the producer is rewriting this slot: the frame is being overwritten, look again
        }
    }
}
