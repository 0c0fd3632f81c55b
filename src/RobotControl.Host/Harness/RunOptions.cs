namespace RobotControl.Host.Harness;

/// <summary>What a headless run does.</summary>
public sealed record RunOptions
{
    /// <summary>The graph file.</summary>
    public required string GraphPath { get; init; }

    /// <summary>
    /// True: the virtual robot (real firmware, simulated motors) on a virtual clock, stepped deterministically as fast
    /// as the machine goes. False: the graph's transport on the system clock, in real time.
    /// </summary>
    public bool Virtual { get; init; } = true;

    /// <summary>The transport to open instead of the graph's (real-time runs; null: the graph's).</summary>
    public string? Transport { get; init; }

    /// <summary>
    /// False (the default): when the robot faults (a module stops its motors, stops answering, loses its position)
    /// the run stops commanding, switches the motors off and reports the fault. True: the run goes on.
    /// </summary>
    public bool ContinueOnFault { get; init; }

    /// <summary>Cancelled to stop the run early (Ctrl+C, SIGTERM): the report is then marked interrupted.</summary>
    public CancellationToken Stop { get; init; }

    /// <summary>
    /// Cancelled when an operator asks for an emergency stop from outside the run (the command line's E-STOP key): the
    /// supervisor trips <c>operator</c> in the next bus cycle (hold, E_STOP) and the run goes on, holding, as after any
    /// hold trip. The source in the report is <c>cli</c>.
    /// </summary>
    public CancellationToken EmergencyStop { get; init; }

    /// <summary>
    /// Cancelled when the surgeon's station asks for an emergency stop over the link (<c>--link</c>, docs/link.md): as
    /// <see cref="EmergencyStop"/>, with source <c>link</c> in the report.
    /// </summary>
    public CancellationToken LinkEmergencyStop { get; init; }

    /// <summary>
    /// The GC latency mode of a real-time run, set for the run and restored after it. SustainedLowLatency by default:
    /// `bench realtime` measured 0.89 % deadline misses with it and 8.1 % with the default (Interactive), 120 s each.
    /// </summary>
    public System.Runtime.GCLatencyMode RealtimeGcLatency { get; init; } = System.Runtime.GCLatencyMode.SustainedLowLatency;

    /// <summary>Scheduling of the real-time threads (priority, CPU); null: normal.</summary>
    public Realtime.RealtimeThreads? Threads { get; init; }

    /// <summary>Loop time to run.</summary>
    public TimeSpan Duration { get; init; } = TimeSpan.FromSeconds(20);

    /// <summary>
    /// Virtual runs: whether a tick's CPU time counts against its period (<see cref="Session.VirtualTickCost.Measured"/>,
    /// the default: a graph too slow for its rate misses) or ticks take no loop time
    /// (<see cref="Session.VirtualTickCost.Free"/>: the run is exactly reproducible; <c>--tick-cost free</c>).
    /// </summary>
    public Session.VirtualTickCost TickCost { get; init; } = Session.VirtualTickCost.Measured;

    /// <summary>Faults injected into the virtual robot.</summary>
    public FaultInjection Inject { get; init; } = FaultInjection.None;

    /// <summary>Seed of the virtual robot's random sources (noise, wire faults).</summary>
    public int Seed { get; init; } = 1;

    /// <summary>How often (loop time) progress is reported.</summary>
    public TimeSpan ProgressInterval { get; init; } = TimeSpan.FromMilliseconds(250);

    /// <summary>
    /// Without a pedal wired to the robot node the harness is the surgeon: after a soft trip (a short host stall, the
    /// master timeout, a jump) puts the run back at PEDAL_UP, it presses the pedal again this long after (default 200
    /// ms); null: never, the run stays at PEDAL_UP.
    /// </summary>
    public TimeSpan? ReEngageAfter { get; init; } = TimeSpan.FromMilliseconds(200);

    /// <summary>Record the session to an MCAP file (<c>--record</c>); null: no recording.</summary>
    public Recording.RecordingOptions? Record { get; init; }

    /// <summary>Settings of graph instances replaced for this run (<c>--set</c>), validated as the file's own.</summary>
    public IReadOnlyList<RobotControl.Runtime.GraphFiles.SettingOverride> SettingOverrides { get; init; } = [];
}

/// <summary>A progress sample of a running harness.</summary>
/// <param name="Elapsed">Loop time so far.</param>
/// <param name="Duration">Loop time planned.</param>
/// <param name="Ticks">Ticks so far.</param>
/// <param name="DeadlineMisses">Deadline misses so far.</param>
/// <param name="TrackingRmsMm">RMS tracking error so far.</param>
/// <param name="TrackingNowMm">Largest current tracking error over the arms.</param>
/// <param name="Faults">Faults so far.</param>
/// <param name="RobotFaults">The robot's fault flags now.</param>
public sealed record RunProgress(TimeSpan Elapsed, TimeSpan Duration, long Ticks, long DeadlineMisses, double TrackingRmsMm, double TrackingNowMm, int Faults, string RobotFaults)
{
    /// <summary>The supervisor's run level now, as the reports name it (e.g. <c>PEDAL_DOWN</c>).</summary>
    public string RunLevel { get; init; } = string.Empty;

    /// <summary>Trips so far.</summary>
    public int Trips { get; init; }

    /// <summary>The last trip in one line, or null.</summary>
    public string? LastTrip { get; init; }
}
