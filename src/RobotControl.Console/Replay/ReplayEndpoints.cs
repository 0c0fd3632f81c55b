using System.Globalization;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Replay;

/// <summary>
/// The replay's controls: <c>GET /api/replay</c> (position, duration, rate, playing, the run levels and trips on the
/// timeline) and <c>POST /api/replay</c> <c>{"play": bool, "rate": 0.25..4, "seek_s": seconds}</c> (any of them).
/// </summary>
internal static class ReplayEndpoints
{
    public static void Map(IEndpointRouteBuilder app, ReplaySession replay)
    {
        app.MapGet("/api/replay", () => ApiEndpoints.Json(View(replay)));
        app.MapPost("/api/replay", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<ReplayBody>(request, "replay").ConfigureAwait(false);
            if (body is null || (body.Play is null && body.Rate is null && body.SeekS is null))
            {
                return ApiEndpoints.Error(StatusCodes.Status400BadRequest, problem ?? "replay: give {\"play\": true|false, \"rate\": 0.25..4, \"seek_s\": seconds} (any of them)");
            }

            if (body.Rate is { } rate && !(rate >= ReplaySession.MinRate && rate <= ReplaySession.MaxRate))
            {
                return ApiEndpoints.Error(StatusCodes.Status400BadRequest, string.Create(CultureInfo.InvariantCulture, $"replay: rate {rate}: give {ReplaySession.MinRate} to {ReplaySession.MaxRate}"));
            }

            if (body.Rate is { } r)
            {
                replay.Rate(r);
            }

            if (body.SeekS is { } seek)
            {
                replay.Seek(seek);
            }

            if (body.Play is { } play)
            {
                replay.Play(play);
            }

            replay.Pump();
            return ApiEndpoints.Json(View(replay));
        });
    }

    private static object View(ReplaySession replay) => new
    {
        PositionS = replay.PositionSeconds,
        DurationS = replay.DurationSeconds,
        replay.Status.Session,
        replay.Timeline,
        replay.Truncated,
    };
}

/// <summary>Body of <c>POST /api/replay</c>.</summary>
/// <param name="Play">Play (true) or pause.</param>
/// <param name="Rate">Playback rate, 0.25 to 4.</param>
/// <param name="SeekS">Position to move to, seconds from the start.</param>
internal sealed record ReplayBody(bool? Play, double? Rate, [property: System.Text.Json.Serialization.JsonPropertyName("seek_s")] double? SeekS);
