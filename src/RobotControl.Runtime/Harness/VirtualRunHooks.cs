using RobotControl.Bus.Transports;
using RobotControl.Runtime.Loop;

namespace RobotControl.Runtime.Harness;

/// <summary>Measurement hooks into a virtual run (benchmarks).</summary>
internal sealed record VirtualRunHooks
{
    /// <summary>Wraps the host's end of the virtual bus (e.g. to timestamp frames); gets the link and the virtual clock.</summary>
    public Func<IByteLink, TimeProvider, IByteLink>? WrapLink { get; init; }

    /// <summary>Runs each tick (must call <see cref="ControlLoop.Step"/> exactly once).</summary>
    public Action<ControlLoop>? AroundTick { get; init; }
}
