using System.Runtime.CompilerServices;

namespace RobotControl.Plugins.Link;

/// <summary>One decoded sample as the subscriber thread hands it to the loop (a value type for <c>LatestValue</c>).</summary>
internal struct LinkSample
{
    /// <summary>The sender's sequence number (1 for its first sample).</summary>
    public long Sequence;

    /// <summary>Identifies one run of the sender: a new value starts its sequence again.</summary>
    public uint Sender;

    /// <summary>The sender's loop time at the tick that made the sample, ns since its first tick.</summary>
    public long LoopNs;

    /// <summary>The sender's wall clock at that tick, ns since the Unix epoch.</summary>
    public long WallNs;

    /// <summary>Receiver's wall clock at arrival minus <see cref="WallNs"/>, ms, at least 0.</summary>
    public double TransitMs;

    /// <summary>The values, in the order of the link's signals.</summary>
    public SampleValues Values;
}

/// <summary>Fixed storage of <see cref="Capacity"/> doubles (no allocation when copied).</summary>
[InlineArray(Capacity)]
internal struct SampleValues
{
    /// <summary>Most signals one link carries.</summary>
    public const int Capacity = 64;

    private double _first;
}
