using RobotControl.Bus.Transports;
using RobotControl.Host.Session;
using RobotControl.Runtime.Loop;

namespace RobotControl.Host.Harness;

/// <summary>Measurement hooks into a run (benchmarks, tests); <see cref="AroundTick"/> applies to virtual runs only.</summary>
internal sealed record VirtualRunHooks
{
    /// <summary>Wraps the host's end of the virtual bus (e.g. to timestamp frames); gets the link and the virtual bus clock.</summary>
    public Func<IByteLink, TimeProvider, IByteLink>? WrapLink { get; init; }

    /// <summary>Runs each tick (must call <see cref="ControlLoop.Step"/> exactly once); gets the loop and the tick's timestamp on the bus clock's timeline.</summary>
    public Action<ControlLoop, long>? AroundTick { get; init; }

    /// <summary>Runs once after the last tick, before the session closes (tests read the virtual modules back).</summary>
    public Action<RobotSession>? AfterRun { get; init; }
}
