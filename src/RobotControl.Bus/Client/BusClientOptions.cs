namespace RobotControl.Bus.Client;

/// <summary>Timing and retry policy of a <see cref="BusClient"/>.</summary>
public sealed record BusClientOptions
{
    /// <summary>
    /// How long to wait for a reply beyond its wire time (module turnaround, return delay, adapter latency). The
    /// default suits the virtual bus and direct UARTs; USB adapters add their latency timer (set it to 1 ms).
    /// </summary>
    public TimeSpan ResponseMargin { get; init; } = TimeSpan.FromMicroseconds(500);

    /// <summary>Extra tries after a timeout or a corrupted reply (reads, writes, pings).</summary>
    public int Retries { get; init; } = 2;

    /// <summary>How long a broadcast ping listens for answers after the last one.</summary>
    public TimeSpan DiscoveryWindow { get; init; } = TimeSpan.FromMilliseconds(20);
}
