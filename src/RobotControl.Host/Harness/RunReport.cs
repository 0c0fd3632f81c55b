using System.Text;
using System.Text.Json;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;

namespace RobotControl.Host.Harness;

/// <summary>
/// The outcome of a headless run, written as <c>report.json</c>:
/// <c>{"duration_s", "ticks", "deadline_misses", "tick_us": {"median", "p99", "max"}, "tracking_error_mm": {"rms",
/// "max"}, "bus": {"frames", "crc_errors", "timeouts", "retries", "late_replies"}, "faults": [...], "interrupted", "stopped_on_fault",
/// "scheduling" and "compiled_after_start" (real time), "stop": {"modules", "torque_off", "torque_on", "latched_errors", "unreachable"}}, "safety": {...}}</c>
/// (<see cref="SafetyReport"/>).
/// </summary>
/// <param name="DurationSeconds">Loop time covered, seconds.</param>
/// <param name="Ticks">Ticks run.</param>
/// <param name="DeadlineMisses">Ticks that missed their deadline on the loop clock.</param>
/// <param name="TickMedianUs">Median tick time (CPU, Stopwatch), microseconds.</param>
/// <param name="TickP99Us">99th-percentile tick time, microseconds.</param>
/// <param name="TickMaxUs">Longest tick, microseconds.</param>
/// <param name="TrackingRmsMm">RMS tracking error, mm.</param>
/// <param name="TrackingMaxMm">Largest tracking error, mm.</param>
/// <param name="Bus">Bus statistics.</param>
/// <param name="Faults">Everything that went wrong, in time order.</param>
/// <param name="Safety">The safety supervisor's run levels and trips (null: the run had none).</param>
public sealed record RunReport(
    double DurationSeconds,
    long Ticks,
    long DeadlineMisses,
    double TickMedianUs,
    double TickP99Us,
    double TickMaxUs,
    double TrackingRmsMm,
    double TrackingMaxMm,
    BusReport Bus,
    IReadOnlyList<FaultEntry> Faults,
    SafetyReport? Safety = null)
{
    /// <summary>True when the run was stopped early by a request (Ctrl+C, SIGTERM).</summary>
    public bool Interrupted { get; init; }

    /// <summary>The robot fault that stopped the run (null: none did).</summary>
    public string? StoppedOnFault { get; init; }

    /// <summary>The modules read back after the motors were switched off (null: not checked).</summary>
    public StopCheck? Stop { get; init; }

    /// <summary>How the real-time threads were scheduled (null: a virtual run).</summary>
    public string? Scheduling { get; init; }

    /// <summary>What the JIT compiled on the real-time threads once they ran (null: a virtual run).</summary>
    public CompiledAfterStart? Compiled { get; init; }

    /// <summary>What the session recording wrote (<c>--record</c>; null: not recorded). Not part of <c>report.json</c>.</summary>
    public Recording.RecordingSummary? Recording { get; init; }

    /// <summary>The loop's figures as every run report writes them: <c>duration_s</c>, <c>ticks</c>, <c>deadline_misses</c>, <c>tick_us</c> {median, p99, max}.</summary>
    internal static void WriteLoop(Utf8JsonWriter w, double durationSeconds, long ticks, long deadlineMisses, double medianUs, double p99Us, double maxUs)
    {
        w.WriteNumber("duration_s", Math.Round(durationSeconds, 6));
        w.WriteNumber("ticks", ticks);
        w.WriteNumber("deadline_misses", deadlineMisses);
        w.WriteStartObject("tick_us");
        w.WriteNumber("median", Math.Round(medianUs, 2));
        w.WriteNumber("p99", Math.Round(p99Us, 2));
        w.WriteNumber("max", Math.Round(maxUs, 2));
        w.WriteEndObject();
    }

    /// <summary>The report as JSON in the documented schema.</summary>
    public string ToJson()
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            WriteLoop(w, DurationSeconds, Ticks, DeadlineMisses, TickMedianUs, TickP99Us, TickMaxUs);
            w.WriteStartObject("tracking_error_mm");
            w.WriteNumber("rms", Math.Round(TrackingRmsMm, 4));
            w.WriteNumber("max", Math.Round(TrackingMaxMm, 4));
            w.WriteEndObject();
            w.WriteStartObject("bus");
            w.WriteNumber("frames", Bus.Frames);
            w.WriteNumber("crc_errors", Bus.CrcErrors);
            w.WriteNumber("timeouts", Bus.Timeouts);
            w.WriteNumber("retries", Bus.Retries);
            w.WriteNumber("late_replies", Bus.LateReplies);
            w.WriteEndObject();
            w.WriteStartArray("faults");
            foreach (var f in Faults)
            {
                w.WriteStartObject();
                w.WriteNumber("time_s", Math.Round(f.TimeSeconds, 4));
                w.WriteString("source", f.Source);
                w.WriteString("message", f.Message);
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteBoolean("interrupted", Interrupted);
            w.WriteString("stopped_on_fault", StoppedOnFault);
            if (Scheduling is not null)
            {
                w.WriteString("scheduling", Scheduling);
            }

            Compiled?.Write(w);

            Stop?.Write(w);
            Safety?.Write(w);
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray()) + Environment.NewLine;
    }
}

/// <summary>Bus statistics of a run.</summary>
/// <param name="Frames">Frames exchanged with the modules (requests addressed to them plus valid replies).</param>
/// <param name="CrcErrors">Replies dropped for a bad CRC.</param>
/// <param name="Timeouts">Replies that did not arrive in time.</param>
/// <param name="Retries">Requests sent again.</param>
/// <param name="LateReplies">Status frames that came after their request was given up on (none taken as a reply).</param>
public sealed record BusReport(long Frames, long CrcErrors, long Timeouts, long Retries, long LateReplies = 0);

/// <summary>One fault in a run.</summary>
/// <param name="TimeSeconds">Run time, seconds (when known; otherwise the end of the run).</param>
/// <param name="Source">Where: a plug-in instance, <c>robot</c> or <c>harness</c>.</param>
/// <param name="Message">What happened.</param>
public sealed record FaultEntry(double TimeSeconds, string Source, string Message);
