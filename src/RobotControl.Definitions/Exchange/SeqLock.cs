namespace RobotControl.Definitions.Exchange;

/// <summary>
/// The one sequence lock of the code base: a fixed-length run of values published by one writer thread and read by
/// any number of readers without locks or allocation. The writer never waits; a reader retries while a write is in
/// progress (a few nanoseconds) and always sees one complete write, never a mix of two. Used for the robot's
/// setpoints and feedback (vectors of doubles) and, through the SDK's <c>LatestValue</c>, for device samples.
/// </summary>
/// <typeparam name="T">The element (copied on every write and read).</typeparam>
public sealed class SeqLock<T>
    where T : struct
{
    private readonly T[] _values;
    private int _sequence;

    /// <summary>A lock over <paramref name="length"/> values, all default until the first write.</summary>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="length"/> is below 1.</exception>
    public SeqLock(int length)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(length, 1);
        _values = new T[length];
    }

    /// <summary>Values per write.</summary>
    public int Length => _values.Length;

    /// <summary>Number of completed writes.</summary>
    public int Version => Volatile.Read(ref _sequence) >> 1;

    /// <summary>Publishes the first <see cref="Length"/> values of <paramref name="values"/> (one writer thread only).</summary>
    public void Write(ReadOnlySpan<T> values)
    {
        var s = _sequence;
        Volatile.Write(ref _sequence, s + 1); // odd: write in progress
        Interlocked.MemoryBarrier();
        values[.._values.Length].CopyTo(_values);
        Volatile.Write(ref _sequence, s + 2); // even: stable
    }

    /// <summary>Copies the latest complete write into <paramref name="destination"/>; returns the number of writes it is.</summary>
    public int Read(Span<T> destination)
    {
        var spinner = default(SpinWait);
        while (true)
        {
            var before = Volatile.Read(ref _sequence);
            if ((before & 1) == 0)
            {
                _values.AsSpan().CopyTo(destination);
                Interlocked.MemoryBarrier();
                if (Volatile.Read(ref _sequence) == before)
                {
                    return before >> 1;
                }
            }

            spinner.SpinOnce(sleep1Threshold: -1);
        }
    }
}
