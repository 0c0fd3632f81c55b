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
    double TrackingRmsMm,
    double TrackingMaxMm,
    double TrackingRmsOverVirtual,
    double AllocatedBytesPerTick,
    double AllocatedBytesPerBusCycle,
    int Gen0Collections,
    int Gen2Collections,
    bool TorqueOffAtStop,
    IReadOnlyList<string> StopProblems,
    PlatformFloor? PlatformFloor,
    double StealMs)
{
    /// <summary>One summary line for the console.</summary>
    public string Line() => string.Create(CultureInfo.InvariantCulture,
        $"  {Ticks} ticks, {DeadlineMisses} misses ({DeadlineMissFraction * 100:F3} %), jitter p50/p99/p99.9/max {TickStartJitterUs.P50:F0}/{TickStartJitterUs.P99:F0}/{TickStartJitterUs.P999:F0}/{TickStartJitterUs.Max:F0} us, "
        + $"bus {BusCyclesPerSecond:F0}/s period p50/p99/p99.9/max {BusCyclePeriodUs.P50:F0}/{BusCyclePeriodUs.P99:F0}/{BusCyclePeriodUs.P999:F0}/{BusCyclePeriodUs.Max:F0} us, "
        + $"late {LateReplies}, crc {CrcErrors}, timeouts {Timeouts}, retries {Retries}, watchdog {WatchdogFaults}, trips {SafetyTrips.Count}, "
        + $"tracking {TrackingRmsMm:F3}/{TrackingMaxMm:F3} mm ({TrackingRmsOverVirtual:F2}x virtual), alloc {AllocatedBytesPerTick:F1} B/tick, gen0 {Gen0Collections}, stolen {StealMs:F0} ms, {Scheduling}{(LoadProblem is null ? "" : "; " + LoadProblem)}")
        + FloorLine();

    private string FloorLine() => PlatformFloor switch
    {
        null => string.Empty,
        { Problem: { } problem } => $"\n  platform floor: {problem}",
        { WakeUpLatencyUs: { } w } f => string.Create(CultureInfo.InvariantCulture, $"\n  platform floor (cyclictest, {f.Seconds:F0} s before the run): wake-up latency p50/p99/p99.9/max {w.P50:F0}/{w.P99:F0}/{w.P999:F0}/{w.Max:F0} us, {f.Overflows} over {PlatformFloor.HistogramUs} us, stolen {f.StealMs:F0} ms"),
        _ => string.Empty,
    };
}
