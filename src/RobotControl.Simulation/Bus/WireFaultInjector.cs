using RobotControl.Simulation.Models;

namespace RobotControl.Simulation.Bus;

/// <summary>The wire's faults (<see cref="WireFaults"/>) applied to bytes in flight from a seeded noise source, with counts of the bytes they hit.</summary>
internal sealed class WireFaultInjector(int seed)
{
    private readonly NoiseSource _noise = new(seed);

    /// <summary>The faults on the wire now.</summary>
    public WireFaults Faults { get; set; } = WireFaults.None;

    /// <summary>Bytes the faults corrupted.</summary>
    public long CorruptedBytes { get; private set; }

    /// <summary>Bytes the faults dropped.</summary>
    public long DroppedBytes { get; private set; }

    /// <summary>Copies <paramref name="source"/> to <paramref name="destination"/> through the faults; returns the bytes that arrive.</summary>
    public int Apply(ReadOnlySpan<byte> source, Span<byte> destination)
    {
        var faults = Faults;
        if (faults.BitErrorRate <= 0 && faults.ByteDropRate <= 0)
        {
            source.CopyTo(destination);
            return source.Length;
        }

        var n = 0;
        foreach (var b in source)
        {
            if (faults.ByteDropRate > 0 && _noise.Uniform() < faults.ByteDropRate)
            {
                DroppedBytes++;
                continue;
            }

            var value = b;
            for (var bit = 0; bit < 8 && faults.BitErrorRate > 0; bit++)
            {
                if (_noise.Uniform() < faults.BitErrorRate)
                {
                    value ^= (byte)(1 << bit);
                }
            }

            if (value != b)
            {
                CorruptedBytes++;
            }

            destination[n++] = value;
        }

        return n;
    }
}
