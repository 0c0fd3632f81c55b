using RobotControl.Bus.Transports;
using RobotControl.Robot.Control;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;

namespace RobotControl.Host.Session;

/// <summary>What a <see cref="RobotSession"/> brings up.</summary>
public sealed record SessionOptions
{
    /// <summary>The graph file (it names the robot file and the transport).</summary>
    public required string GraphPath { get; init; }

    /// <summary>
    /// True: the virtual robot (real firmware, simulated motors) on a virtual clock, stepped by a
    /// <see cref="VirtualSchedule"/>. False: the graph's transport on the system clock, bus and loop on threads of
    /// their own.
    /// </summary>
    public bool Virtual { get; init; } = true;

    /// <summary>
    /// The transport to open instead of the graph's (<c>--transport</c>; null: the graph's). Check it with
    /// <see cref="TransportOverride.Check"/> first. Ignored by a virtual session.
    /// </summary>
    public string? Transport { get; init; }

    /// <summary>Seed of the virtual robot's random sources (noise, wire faults).</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Settings of graph instances overridden for this session (<c>--set instance.setting=value</c>).</summary>
    public IReadOnlyList<SettingOverride> SettingOverrides { get; init; } = [];

    /// <summary>Wraps the host's end of a virtual bus (e.g. to timestamp frames); gets the link and the bus clock.</summary>
    public Func<IByteLink, TimeProvider, IByteLink>? WrapLink { get; init; }

    /// <summary>How the robot runs its bus (polls); null: the defaults.</summary>
    public RobotControl.Robot.Bus.BusRobotOptions? Robot { get; init; }

    /// <summary>Makes the loop's observer (called after every tick) from the robot node and the robot.</summary>
    public Func<RobotNode, IRobotPort, ITickObserver>? Observer { get; init; }
}
