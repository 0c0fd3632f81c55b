namespace RobotControl.Plugins.Sdk.Exchange;

/// <summary>
/// A single-producer, single-consumer ring of fixed-width rows of doubles: the control loop pushes a row per tick
/// without locks or allocation, a background thread drains rows to a file. When the ring is full the row is dropped
/// and counted (the loop never waits for the disk).
/// </summary>
public sealed class SampleRing
{
    private readonly double[] _rows;
    private readonly int _capacity;
    private long _head; // next row to write (producer)
    private long _tail; // next row to read (consumer)
    private long _dropped;

    /// <summary>Creates a ring of <paramref name="capacity"/> rows of <paramref name="width"/> values.</summary>
    public SampleRing(int width, int capacity)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(width, 1);
        ArgumentOutOfRangeException.ThrowIfLessThan(capacity, 2);
        Width = width;
        _capacity = capacity;
        _rows = new double[width * capacity];
    }

    /// <summary>Values per row.</summary>
    public int Width { get; }

    /// <summary>Rows dropped because the ring was full.</summary>
    public long Dropped => Volatile.Read(ref _dropped);

    /// <summary>Rows waiting to be read.</summary>
    public int Count => (int)(Volatile.Read(ref _head) - Volatile.Read(ref _tail));

    /// <summary>Reserves the next row for writing (producer); empty when the ring is full (the row is counted as dropped).</summary>
    public Span<double> BeginWrite()
    {
        var head = Volatile.Read(ref _head);
        if (head - Volatile.Read(ref _tail) >= _capacity)
        {
            Interlocked.Increment(ref _dropped);
            return [];
        }

        return _rows.AsSpan((int)(head % _capacity) * Width, Width);
    }

    /// <summary>Publishes the row reserved by <see cref="BeginWrite"/> (producer).</summary>
    public void EndWrite() => Volatile.Write(ref _head, Volatile.Read(ref _head) + 1);

    /// <summary>Copies the oldest row into <paramref name="row"/> (consumer); false when empty.</summary>
    public bool TryRead(Span<double> row)
    {
        var tail = Volatile.Read(ref _tail);
        if (tail == Volatile.Read(ref _head))
        {
            return false;
        }

        _rows.AsSpan((int)(tail % _capacity) * Width, Width).CopyTo(row);
        Volatile.Write(ref _tail, tail + 1);
        return true;
    }
}
