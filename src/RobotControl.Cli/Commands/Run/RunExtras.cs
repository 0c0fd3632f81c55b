using RobotControl.Bus.Transports;
using RobotControl.Cli.Commands.Recording;
using RobotControl.Host.Realtime;
using RobotControl.Host.Session;
using RobotControl.Plugins.Link.Stations;

namespace RobotControl.Cli.Commands.Run;

/// <summary><c>run</c>'s transport override and fault policy, checked before anything is loaded or opened.</summary>
/// <param name="Transport">The <c>--transport</c> value (null: the graph's).</param>
/// <param name="ContinueOnFault">The <c>--continue-on-fault</c> flag.</param>
/// <param name="RtPriority">The <c>--rt-priority</c> value (SCHED_FIFO 1..99; 0: normal scheduling).</param>
/// <param name="Cpu">The <c>--cpu</c> value (null: any CPU).</param>
internal sealed record RunExtras(string? Transport, bool ContinueOnFault, int RtPriority = 0, int? Cpu = null)
{
    /// <summary>The <c>--record</c> options (null: no recording).</summary>
    public RecordRequest? Record { get; init; }

    /// <summary>The <c>--link</c> value: the NATS server the stations' commands go through (null: none).</summary>
    public string? Link { get; init; }

    /// <summary>The <c>--station</c> value: the robot station's name on the link.</summary>
    public string? Station { get; init; }

    /// <summary>The <c>--link-plaintext-remote</c> flag: a plain-text server off the loopback interface is allowed.</summary>
    public bool LinkPlaintextRemote { get; init; }

    /// <summary>The robot station's command address, or null without <c>--link</c>.</summary>
    /// <exception cref="FormatException">One line: one of <c>--link</c> and <c>--station</c> without the other, or either malformed.</exception>
    public StationAddress? LinkAddress() => (Link, Station) switch
    {
        (null, null) => null,
        (null, _) => throw new FormatException("--station names the robot station on a link: give the server with --link nats://host:4222 too"),
        (_, null) => throw new FormatException("--link needs --station <name>: the robot station's name on the server (e.g. lb1)"),
        var (link, station) => StationAddress.Parse(link, station, LinkPlaintextRemote),
    };

    /// <summary>The <c>--tick-cost</c> value.</summary>
    public VirtualTickCost TickCost { get; init; } = VirtualTickCost.Measured;

    /// <summary>The tick cost of a run that is virtual or not (<paramref name="isVirtual"/>).</summary>
    /// <exception cref="FormatException">One line: <c>--tick-cost free</c> on a real-time run, whose ticks take the wall clock's time.</exception>
    public VirtualTickCost TickCostFor(bool isVirtual) =>
        isVirtual || TickCost == VirtualTickCost.Measured
            ? TickCost
            : throw new FormatException("--tick-cost free applies to --virtual runs: a real-time run's ticks take the wall clock's time");

    /// <summary>The real-time threads' scheduling.</summary>
    /// <exception cref="FormatException">One line naming the option out of range.</exception>
    public RealtimeThreads Threads()
    {
        if (RtPriority is < 0 or > 99)
        {
            throw new FormatException($"--rt-priority {RtPriority}: give 1..99 (SCHED_FIFO), or 0 for normal scheduling");
        }

        if (Cpu is { } cpu && (cpu < 0 || cpu >= Environment.ProcessorCount))
        {
            throw new FormatException($"--cpu {cpu}: this machine has CPUs 0..{Environment.ProcessorCount - 1}");
        }

        return new RealtimeThreads(RtPriority, Cpu);
    }

    /// <summary>Checks the override; returns whether the run is virtual (<c>--virtual</c>, or a <c>virtual</c> transport).</summary>
    /// <exception cref="FormatException">One line: the transport is malformed, names a missing device, or contradicts <c>--virtual</c>.</exception>
    public bool ResolveVirtual(bool isVirtual)
    {
        if (Transport is null)
        {
            return isVirtual;
        }

        if (Transport.Equals("virtual", StringComparison.OrdinalIgnoreCase))
        {
            return true;
        }

        var uri = TransportOverride.Check(Transport);
        if (uri.Kind == LinkKind.Virtual)
        {
            return true;
        }

        return isVirtual
            ? throw new FormatException($"--transport {Transport} and --virtual contradict each other: give one")
            : false;
    }
}
