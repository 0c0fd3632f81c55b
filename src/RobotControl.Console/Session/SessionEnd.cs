using System.Text.Json;
using RobotControl.Host.Session;

namespace RobotControl.WebConsole.Session;

/// <summary>
/// How a console session ended: its last status, the stop's read-back of every module, the event log and the
/// component timings. <c>robotctl console</c> prints the stop and writes this as the session's report.
/// </summary>
/// <param name="Status">The status just before the stop (ticks, misses, bus counters, faults).</param>
/// <param name="Stop">What the modules said after the motors were switched off; null when the session never reached a robot.</param>
/// <param name="Events">The event log, oldest first, ending with the stop.</param>
/// <param name="Timings">Per-component timing of the session thread and the loop.</param>
public sealed record SessionEnd(SessionStatus Status, StopCheck? Stop, IReadOnlyList<EventEntry> Events, IReadOnlyList<ComponentTiming> Timings)
{
    private static readonly JsonSerializerOptions Options = new(JsonSerializerDefaults.Web)
    {
        WriteIndented = true,
        PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower,
        NumberHandling = System.Text.Json.Serialization.JsonNumberHandling.AllowNamedFloatingPointLiterals,
    };

    /// <summary>True when every module answered the stop's read-back with torque off.</summary>
    public bool TorqueOff => Stop?.TorqueOff == true;

    /// <summary>The report: status, stop (with <c>torque_off</c>), events and timings, in the run report's snake_case.</summary>
    public string ToJson() => JsonSerializer.Serialize(
        new
        {
            Status,
            Stop = Stop is null ? null : new { Stop.Modules, Stop.TorqueOff, Stop.TorqueOn, Stop.LatchedErrors, Stop.Unreachable },
            Events,
            Timings,
        },
        Options);
}
