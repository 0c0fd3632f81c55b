namespace RobotControl.Robot.Exchange;

/// <summary>
/// A fixed-length vector of doubles published by one writer thread and read by any number of readers without locks
/// or allocation (a sequence lock: readers retry while a write is in progress). Readers always see one complete
/// write, never a mix of two.
/// </summary>
internal sealed class SeqLockValues
{
    private readonly double[] _values;
    private int _sequence;

    public SeqLockValues(int length) => _values = new double[length];

    public int Length => _values.Length;

    /// <summary>Number of completed writes.</summary>
    public int Version => Volatile.Read(ref _sequence) >> 1;

    /// <summary>Publishes <paramref name="values"/> (single writer).</summary>
    public void Write(ReadOnlySpan<double> values)
    {
        var s = _sequence;
        Volatile.Write(ref _sequence, s + 1);
        Interlocked.MemoryBarrier();
        values[.._values.Length].CopyTo(_values);
        Volatile.Write(ref _sequence, s + 2);
    }

    /// <summary>Copies the latest complete write into <paramref name="destination"/>.</summary>
    public void Read(Span<double> destination)
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
                    return;
                }
            }

            spinner.SpinOnce(sleep1Threshold: -1);
        }
    }
}
