using System.Runtime.InteropServices;
using RobotControl.Definitions.Exchange;

namespace RobotControl.Plugins.Sdk.Exchange;

/// <summary>
/// Hands the latest value of a struct from one writer thread (a device's I/O thread) to one reader (the control
/// loop) without locks, through the code base's one sequence lock (<see cref="SeqLock{T}"/>): the writer never
/// waits, the reader never sees a torn value. Allocation-free.
/// </summary>
/// <typeparam name="T">The value (keep it small; copied on every publish and read).</typeparam>
public sealed class LatestValue<T>
    where T : struct
{
    private readonly SeqLock<T> _lock = new(1);

    /// <summary>Number of values published so far.</summary>
    public long PublishedCount => _lock.Version;

    /// <summary>Publishes <paramref name="value"/> (one writer thread only).</summary>
    public void Publish(in T value) => _lock.Write(new ReadOnlySpan<T>(in value));

    /// <summary>Reads the latest value; false when nothing was published yet (then <paramref name="value"/> is default).</summary>
    public bool TryRead(out T value)
    {
        value = default;
        return _lock.Read(MemoryMarshal.CreateSpan(ref value, 1)) != 0;
    }
}
