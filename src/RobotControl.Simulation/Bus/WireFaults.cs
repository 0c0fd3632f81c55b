namespace RobotControl.Simulation.Bus;

/// <summary>Faults the virtual wire injects (EMI from cautery): bit errors and lost bytes, seeded.</summary>
public sealed record WireFaults
{
    /// <summary>Probability that any one bit on the wire is flipped.</summary>
    public double BitErrorRate { get; init; }

    /// <summary>Probability that a byte is lost (no receiver sees it).</summary>
    public double ByteDropRate { get; init; }

    /// <summary>No faults.</summary>
    public static WireFaults None { get; } = new();
}
