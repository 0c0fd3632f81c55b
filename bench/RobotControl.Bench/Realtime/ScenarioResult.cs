using System.Globalization;
using RobotControl.Host.Realtime;

namespace RobotControl.Bench.Realtime;

/// <summary>p50 / p99 / p99.9 / max of a distribution, microseconds.</summary>
internal sealed record Quantiles(double P50, double P99, double P999, double Max);

/// <summary>What one <c>bench realtime</c> scenario measured (serialised to the JSON report).</summary>
internal sealed record ScenarioResult(
    string Scenario,
    string GcLatencyMode,
    string Scheduling,
    string? LoadProblem,
    string LoadAverageAtStart,
    string LoadAverageAtEnd,
    long Ticks,
    long DeadlineMisses,
    double DeadlineMissFraction,
    Quantiles TickStartJitterUs,
    Quantiles TickTimeUs,
    Quantiles BusCyclePeriodUs,
    double BusCyclesPerSecond,
    long LateReplies,
    long CrcErrors,
    long Timeouts,
    long Retries,
    int WatchdogFaults,
    IReadOnlyList<string> SafetyTrips,
    int SoftTrips,
    int EStops,
    double PedalDownShare,
    int ReEngagements,
    double TrackingRmsMm,
    double TrackingMaxMm,
    double TrackingRmsOverVirtual,
    double AllocatedBytesPerTick,
    double AllocatedBytesPerBusCycle,
    int Gen0Collections,
    int Gen2Collections,
    double GcPauseMs,
    double GcLongestRecentPauseMs,
    bool TorqueOffAtStop,
    IReadOnlyList<string> StopProblems,
    PlatformFloor? PlatformFloor,
    PlatformFloor? PlatformFloorDuringRun,
    double StealMs,
    string Simulator,
    string CompiledAfterStart,
    IReadOnlyList<StartupGap> LongestStartupCycles)
{
    /// <summary>One summary line for the console.</summary>
    public string Line() => string.Create(CultureInfo.InvariantCulture,
        $"  {Ticks} ticks, {DeadlineMisses} misses ({DeadlineMissFraction * 100:F3} %), jitter p50/p99/p99.9/max {TickStartJitterUs.P50:F0}/{TickStartJitterUs.P99:F0}/{TickStartJitterUs.P999:F0}/{TickStartJitterUs.Max:F0} us, "
        + $"bus {BusCyclesPerSecond:F0}/s period p50/p99/p99.9/max {BusCyclePeriodUs.P50:F0}/{BusCyclePeriodUs.P99:F0}/{BusCyclePeriodUs.P999:F0}/{BusCyclePeriodUs.Max:F0} us, "
        + $"late {LateReplies}, crc {CrcErrors}, timeouts {Timeouts}, retries {Retries}, watchdog {WatchdogFaults}, trips {SafetyTrips.Count} ({SoftTrips} soft, {EStops} E-STOP), PEDAL_DOWN {PedalDownShare * 100:F2} % (re-engaged {ReEngagements}), "
        + $"tracking {TrackingRmsMm:F3}/{TrackingMaxMm:F3} mm ({TrackingRmsOverVirtual:F2}x virtual), alloc {AllocatedBytesPerTick:F1} B/tick, gen0 {Gen0Collections} gen2 {Gen2Collections}, GC pauses {GcPauseMs:F1} ms (longest recent {GcLongestRecentPauseMs:F1} ms), stolen {StealMs:F0} ms, {Scheduling}{(LoadProblem is null ? "" : "; " + LoadProblem)}")
        + FloorLine()
        + $"\n  simulator: {Simulator}"
        + $"\n  compiled after start: {CompiledAfterStart}"
        + string.Concat(LongestStartupCycles.Select(g => string.Create(CultureInfo.InvariantCulture, $"\n  long cycle at {g.AtS:F3} s (traced start): {g.CycleMs:F1} ms, {g.ReadWaitMs:F1} ms in reads ({g.EmptyReads} empty), longest with no link call {g.LongestIdleMs:F1} ms")));

    private string FloorLine() => FloorLine(PlatformFloor, "before the run") + FloorLine(PlatformFloorDuringRun, "alongside the run");

    private static string FloorLine(PlatformFloor? floor, string when) => floor switch
    {
        null => string.Empty,
        { Problem: { } problem } => $"\n  platform floor ({when}): {problem}",
        { WakeUpLatencyUs: { } w } f => string.Create(CultureInfo.InvariantCulture, $"\n  platform floor (cyclictest, {f.Seconds:F0} s {when}): wake-up latency p50/p99/p99.9/max {w.P50:F0}/{w.P99:F0}/{w.P999:F0}/{w.Max:F0} us, {f.Overflows} over {PlatformFloor.HistogramUs} us, stolen {f.StealMs:F0} ms"),
        _ => string.Empty,
    };
}
