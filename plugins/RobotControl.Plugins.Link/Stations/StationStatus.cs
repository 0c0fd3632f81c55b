using System.Globalization;
using System.Text.Json;

namespace RobotControl.Plugins.Link.Stations;

/// <summary>
/// What a robot station says of itself on <c>rc.&lt;station&gt;.status</c>, several times a second and at once on a
/// change: its run level, its trips so far and the last one in words.
/// </summary>
/// <param name="RunLevel">The supervisor's run level (e.g. <c>PEDAL_DOWN</c>).</param>
/// <param name="Trips">Trips so far.</param>
/// <param name="LastTrip">The last trip in one line, or null.</param>
public sealed record StationStatus(string RunLevel, int Trips, string? LastTrip)
{
    /// <summary>The message's text.</summary>
    public string ToJson() => JsonSerializer.Serialize(new Dictionary<string, object?> { ["run_level"] = RunLevel, ["trips"] = Trips, ["last_trip"] = LastTrip });

    /// <summary>Reads a message; null for one that is not a status.</summary>
    public static StationStatus? Parse(string? json)
    {
        try
        {
            using var doc = JsonDocument.Parse(json ?? string.Empty);
            var root = doc.RootElement;
            return new StationStatus(
                root.GetProperty("run_level").GetString() ?? string.Empty,
                root.GetProperty("trips").GetInt32(),
                root.TryGetProperty("last_trip", out var trip) && trip.ValueKind == JsonValueKind.String ? trip.GetString() : null);
        }
        catch (Exception ex) when (ex is JsonException or KeyNotFoundException or InvalidOperationException or FormatException)
        {
            return null;
        }
    }

    /// <summary>The line a surgeon's station prints when it changes.</summary>
    public string Line(string station) =>
        string.Create(CultureInfo.InvariantCulture, $"robot station '{station}': {RunLevel}, {Trips} trip(s){(LastTrip is null ? string.Empty : $", last: {LastTrip}")}");
}
