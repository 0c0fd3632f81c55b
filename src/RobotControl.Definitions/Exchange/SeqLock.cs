namespace RobotControl.Definitions.Exchange;

/// <summary>
/// The one sequence lock of the code base: a fixed-length run of values published by one writer thread and read by
/// any number of readers without locks or allocation, and without either side ever waiting for the other. Writes go
/// to two slots in turn; a reader copies the slot of the latest complete write, so a write in progress (even one whose
/// thread was preempted half-way, on a loaded machine) never holds a reader up. A reader retries only when the writer
/// has lapped it (two writes began during its copy) and always sees one complete write, never a mix of two. Used for
/// the robot's setpoints and feedback (vectors of doubles) and, through the SDK's <c>LatestValue</c>, for device samples.
/// </summary>
/// <typeparam name="T">The element (copied on every write and read).</typeparam>
public sealed class SeqLock<T>
    where T : struct
{
    private readonly T[] _values; // two slots: write number w goes to slot w % 2
    private readonly int _length;
    private int _sequence; // 2 x completed writes, +1 while a write is in progress

    /// <summary>A lock over <paramref name="length"/> values, all default until the first write.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="length"/> is below 1.</exception>
    public SeqLock(int length)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(length, 1);
        _length = length;
        _values = new T[2 * length];
    }

    /// <summary>A lock whose sequence starts at <paramref name="sequence"/> (even): for tests of the count wrapping.</summary>
    internal SeqLock(int length, int sequence)
        : this(length)
    {
        _sequence = sequence & ~1;
    }

    /// <summary>Values per write.</summary>
    public int Length => _length;

    /// <summary>Number of completed writes.</summary>
    public int Version => Volatile.Read(ref _sequence) >> 1;

    /// <summary>Publishes the first <see cref="Length"/> values of <paramref name="values"/> (one writer thread only).</summary>
    public void Write(ReadOnlySpan<T> values)
    {
        values[.._length].CopyTo(BeginWrite());
        EndWrite();
    }

    /// <summary>Copies the latest complete write into <paramref name="destination"/>; returns the number of writes it is.</summary>
    public int Read(Span<T> destination)
    {
        while (true)
        {
            var before = Volatile.Read(ref _sequence);
            var completed = before >> 1;
            Slot(completed).CopyTo(destination);
            Interlocked.MemoryBarrier();

            // The slot read is rewritten by write number completed + 2, which begins when the sequence has moved 3 past
            // 2 x completed: until then the copy is whole. (Differences, so that the count may wrap past int.MaxValue.)
            if (unchecked(Volatile.Read(ref _sequence) - (before & ~1)) < 3)
            {
                return completed;
            }
        }
    }

    /// <summary>Opens the next write (odd sequence) and returns its slot; <see cref="EndWrite"/> publishes it. For tests of a write left open.</summary>
    internal Span<T> BeginWrite()
    {
        var s = _sequence;
        Volatile.Write(ref _sequence, s + 1); // odd: write in progress
        Interlocked.MemoryBarrier();
        return Slot((s >> 1) + 1);
    }

    /// <summary>Publishes the write opened by <see cref="BeginWrite"/> (even sequence).</summary>
    internal void EndWrite() => Volatile.Write(ref _sequence, _sequence + 1);

    private Span<T> Slot(int write) => _values.AsSpan((write & 1) * _length, _length);
}
