using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>The surgeon's view's endpoints (see docs/console.md): its hands, pedals and faults, the workspace, the scale factor.</summary>
internal static class SurgeonEndpoints
{
    /// <summary>Maps the reads on <paramref name="api"/> and the scale factor on the operator's <paramref name="actions"/>.</summary>
    public static void Map(RouteGroupBuilder api, RouteGroupBuilder actions, IConsoleSession session)
    {
        api.MapGet("/surgeon", () => ApiEndpoints.Json(session.Surgeon));
        api.MapGet("/workspace", () => ApiEndpoints.Json(session.Workspace));
        actions.MapPut("/hands/{arm}/scale", async (string arm, HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<ValueBody>(request, "scale").ConfigureAwait(false);
            return body?.Value is { } v
                ? ApiEndpoints.Result(await session.SetScaleAsync(arm, v).ConfigureAwait(false))
                : ApiEndpoints.Error(StatusCodes.Status400BadRequest, problem ?? "scale: give {\"value\": <number>}");
        });
    }
}
