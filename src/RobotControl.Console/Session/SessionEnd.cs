using System.Text;
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
        PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower,
        NumberHandling = System.Text.Json.Serialization.JsonNumberHandling.AllowNamedFloatingPointLiterals,
    };

    /// <summary>True when every module answered the stop's read-back with torque off.</summary>
    public bool TorqueOff => Stop?.TorqueOff == true;

    /// <summary>The report: status, stop (as in a run's report: <see cref="StopCheck.Write"/>), events and timings, in snake_case.</summary>
    public string ToJson()
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WritePropertyName("status");
            JsonSerializer.Serialize(w, Status, Options);
            if (Stop is null)
            {
                w.WriteNull("stop"); // the session never reached a robot
            }
            else
            {
                Stop.Write(w);
            }

            w.WritePropertyName("events");
            JsonSerializer.Serialize(w, Events, Options);
            w.WritePropertyName("timings");
            JsonSerializer.Serialize(w, Timings, Options);
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray()) + Environment.NewLine;
    }
}
