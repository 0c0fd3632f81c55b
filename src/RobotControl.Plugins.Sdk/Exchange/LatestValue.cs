namespace RobotControl.Plugins.Sdk.Exchange;

/// <summary>
/// Hands the latest value of a struct from one writer thread (a device's I/O thread) to one reader (the control
/// loop) without locks: a sequence lock. The writer never waits; the reader retries while a write is in progress
/// (a few nanoseconds) and never sees a torn value. Allocation-free.
/// </summary>
/// <typeparam name="T">The value (keep it small; copied on every publish and read).</typeparam>
public sealed class LatestValue<T>
    where T : struct
{
    private T _value;
    private int _sequence;
    private long _published;

    /// <summary>Number of values published so far.</summary>
    public long PublishedCount => Volatile.Read(ref _published);

    /// <summary>Publishes <paramref name="value"/> (one writer thread only).</summary>
    public void Publish(in T value)
    {
        Interlocked.Increment(ref _sequence); // odd: write in progress
        _value = value;
        Interlocked.Increment(ref _sequence); // even: stable
        Interlocked.Increment(ref _published);
    }

    /// <summary>Reads the latest value; false when nothing was published yet (then <paramref name="value"/> is default).</summary>
    public bool TryRead(out T value)
    {
        var spinner = default(SpinWait);
        while (true)
        {
            var before = Volatile.Read(ref _sequence);
            if ((before & 1) == 0)
            {
                value = _value;
                Interlocked.MemoryBarrier();
                if (Volatile.Read(ref _sequence) == before)
                {
                    return before != 0;
                }
            }

            spinner.SpinOnce(sleep1Threshold: -1);
        }
    }
}
