using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// The bring-up page's API (docs/console.md): <c>GET /api/bringup?after=n</c> (the unit, the step and its progress
/// lines after n), <c>POST /api/bringup/commission</c> <c>{"poll": bool}</c>, <c>POST /api/bringup/calibrate</c>
/// <c>{"module": id, "redo": bool}</c> and <c>POST /api/bringup/continue</c> (the operator role), and
/// <c>POST /api/bringup/stop</c> (every console with the token; <c>POST /api/estop</c> stops it too, without one).
/// </summary>
internal static class BringUpEndpoints
{
    public static void Map(IEndpointRouteBuilder app, BringUpSession session, OperatorRole role)
    {
        app.MapGet("/api/bringup", (int? after) =>
        {
            var job = session.Job;
            return ApiEndpoints.Json(new
            {
                session.Unit,
                Job = job is null ? null : new { job.Step, job.State, Prompt = job.State == "waiting" ? Instruction(session.Lines.Last) : null, job.Outcome },
                Lines = session.Lines.After(after ?? 0),
            });
        });
        var api = app.MapGroup("/api/bringup").Witnessed(session, role); // every command is noted, the polls are not
        api.MapPost("/stop", async () => ApiEndpoints.Result(await session.StopAsync("STOP").ConfigureAwait(false)));
        var operate = ApiEndpoints.OperatorOnly(api.MapGroup(string.Empty), role);
        operate.MapPost("/commission", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<CommissionBody>(request, "commission").ConfigureAwait(false);
            return body is null ? ApiEndpoints.Error(StatusCodes.Status400BadRequest, problem ?? "commission: give {\"poll\": true|false}") : ApiEndpoints.Result(session.StartCommission(body.Poll ?? false));
        });
        operate.MapPost("/calibrate", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<CalibrateBody>(request, "calibrate").ConfigureAwait(false);
            return body is null ? ApiEndpoints.Error(StatusCodes.Status400BadRequest, problem ?? "calibrate: give {\"module\": id or null, \"redo\": true|false}") : ApiEndpoints.Result(session.StartCalibration(body.Module, body.Redo ?? false));
        });
        operate.MapPost("/continue", () => ApiEndpoints.Result(session.Continue()));
    }

    /// <summary>The step's question as the page words it: the CLI's "then press Enter" is the page's Continue.</summary>
    private static string? Instruction(string? line) => line?.Replace("then press Enter", "then press Continue", StringComparison.Ordinal);
}

/// <summary>Body of <c>POST /api/bringup/commission</c>.</summary>
/// <param name="Poll">Wait for each module to answer by itself instead of for Continue.</param>
internal sealed record CommissionBody(bool? Poll);

/// <summary>Body of <c>POST /api/bringup/calibrate</c>.</summary>
/// <param name="Module">Only this module's motors (its robot-file ID); null: every module.</param>
/// <param name="Redo">Calibrate motors already calibrated and verified again.</param>
internal sealed record CalibrateBody(int? Module, bool? Redo);
