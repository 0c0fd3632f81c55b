using RobotControl.Host.Harness;
using RobotControl.Host.Realtime;
using RobotControl.Runtime.Discovery;

namespace RobotControl.WebConsole.Adapter;

/// <summary>How the console brings its session up.</summary>
public sealed record LiveSessionOptions
{
    /// <summary>The graph file.</summary>
    public required string GraphPath { get; init; }

    /// <summary>Plug-in types the graph may use.</summary>
    public required PluginCatalog Catalog { get; init; }

    /// <summary>True: the virtual robot (real firmware, simulated motors), paced to real time.</summary>
    public bool Virtual { get; init; }

    /// <summary>A transport that replaces the graph's (serial, usb, tcp); null: the graph's.</summary>
    public string? Transport { get; init; }

    /// <summary>Seed of the virtual robot's random sources.</summary>
    public int Seed { get; init; } = 1;

    /// <summary>Rows of signal history kept for streaming.</summary>
    public int RingCapacity { get; init; } = 16384;

    /// <summary>Faults injected into the virtual robot (<c>silent=</c> only: see <see cref="ConsoleFaults"/>).</summary>
    public FaultInjection Inject { get; init; } = FaultInjection.None;

    /// <summary>
    /// On a real bus, how the session's bus thread and the loop thread are scheduled (SCHED_FIFO priority, CPU pin);
    /// null: normal scheduling. The virtual robot runs paced on the session thread and ignores it.
    /// </summary>
    public RealtimeThreads? Threads { get; init; }

    /// <summary>Wraps the host's end of the bus (benchmarks: timestamp frames); passed to the session layer (<see cref="Host.Session.SessionOptions.WrapLink"/>).</summary>
    public Func<RobotControl.Bus.Transports.IByteLink, TimeProvider, RobotControl.Bus.Transports.IByteLink>? WrapLink { get; init; }

    /// <summary>Record the session to an MCAP file from its start to its stop (<c>--record</c>; docs/recording.md); null: no recording.</summary>
    public Host.Recording.RecordingOptions? Record { get; init; }

    /// <summary>Where the record button's files go (null: the <see cref="Record"/> file's folder, else <c>recordings</c> in the working directory).</summary>
    public string? RecordFolder { get; init; }
}
