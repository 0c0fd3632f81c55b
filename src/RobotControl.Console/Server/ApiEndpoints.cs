using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The JSON API (see docs/console.md). Reads are open to every console with the token, and so is stopping a jog (and
/// the status poll, the holder's heartbeat, renews the operator role); actions (and re-reading parameters, which costs
/// bus time) need the operator role. The emergency stop is not here: <see cref="AccessControl"/>
/// answers it for every console, watching or operating, with or without the token.
/// </summary>
internal static class ApiEndpoints
{
    public static void Map(IEndpointRouteBuilder app, IConsoleSession session, OperatorRole role, string instance)
    {
        var api = app.MapGroup("/api");
        api.MapGet("/status", (HttpContext http) =>
        {
            role.IsHeldBy(ClientOf(http)); // the holder's page polls: an open operator page keeps the role, a closed one loses it
            return Json(new { session.Status, Operator = OperatorView(http, role), Instance = instance });
        });
        api.MapGet("/controllers", () => Json(session.Controllers));
        api.MapGet("/signals", () => Json(session.Signals.Names.Select((n, i) => new { Name = n, Unit = session.Signals.Units[i] })));
        api.MapGet("/events", (long? after) => Json(session.EventsAfter(after ?? 0)));
        api.MapGet("/timings", () => Json(session.Timings));
        api.MapGet("/model", () => Json(session.Model));
        api.MapGet("/recording", () => Json(new { session.RecordingFile }));
        api.MapGet("/model/arm.urdf", () => Results.Text(session.Model.Urdf, "application/xml"));

        api.MapPost("/operator", (HttpContext http) =>
        {
            var client = ClientOf(http);
            if (client is null)
            {
                return Error(StatusCodes.Status400BadRequest, $"operator: name this console with the {OperatorRole.ClientHeader} header");
            }

            return role.TryClaim(client)
                ? Json(OperatorView(http, role))
                : Error(StatusCodes.Status409Conflict, "another console holds the operator role; this one watches");
        }).Witnessed(session, role);
        api.MapDelete("/operator", (HttpContext http) =>
        {
            if (ClientOf(http) is { } client)
            {
                role.Release(client);
            }

            return Json(OperatorView(http, role));
        }).Witnessed(session, role);

        // POST /api/estop is answered by AccessControl, before the token, the rate limits and routing: any console may stop.
        // Stopping a jog needs no role either: any console with the token may stop a motor (it holds where it is).
        api.MapPost("/motors/{motor}/stop", async (string motor) => Result(await session.JogAsync(motor, 0).ConfigureAwait(false))).Witnessed(session, role);
        var actions = OperatorOnly(api.MapGroup(string.Empty).Witnessed(session, role), role); // noted first: a refused command is noted too
        actions.MapPost("/controllers/{id:int}/reload", async (int id) => Result(await session.ReloadParametersAsync(id).ConfigureAwait(false))).RequireRateLimiting(RateLimits.Bus);
        actions.MapPost("/discover", async () => Result(await session.DiscoverAsync().ConfigureAwait(false))).RequireRateLimiting(RateLimits.Bus);
        actions.MapPost("/torque", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<TorqueBody>(request, "torque").ConfigureAwait(false);
            return body?.On is { } on ? Result(await session.TorqueAsync(on).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "torque: give {\"on\": true|false}");
        });
        actions.MapPost("/pedal", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<PedalBody>(request, "pedal").ConfigureAwait(false);
            return body?.Down is { } down ? Result(await session.PedalAsync(down).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "pedal: give {\"down\": true|false}");
        });
        actions.MapPost("/recording", async (HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<RecordBody>(request, "recording").ConfigureAwait(false);
            return body?.On is { } on ? Result(await session.RecordAsync(on).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "recording: give {\"on\": true|false}");
        });
        actions.MapPost("/home", async () => Result(await session.HomeAsync(null).ConfigureAwait(false)));
        actions.MapPost("/faults/clear", async () => Result(await session.ClearFaultsAsync().ConfigureAwait(false)));
        actions.MapPut("/controllers/{id:int}/name", async (int id, HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<NameBody>(request, "name").ConfigureAwait(false);
            return body?.Name is { } name ? Result(await session.RenameAsync(id, name).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "name: give {\"name\": \"...\"}");
        });
        actions.MapPost("/controllers/{id:int}/reboot", async (int id) => Result(await session.RebootAsync(id).ConfigureAwait(false))).RequireRateLimiting(RateLimits.Bus);
        actions.MapPut("/motors/{motor}/parameters/{key}", async (string motor, string key, HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<ValueBody>(request, key).ConfigureAwait(false);
            return body?.Value is { } v ? Result(await session.WriteParameterAsync(motor, key, v).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? $"{key}: give {{\"value\": <number>}}");
        }).RequireRateLimiting(RateLimits.Bus);
        actions.MapPost("/motors/{motor}/jog", async (string motor, HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<JogBody>(request, "jog").ConfigureAwait(false);
            return body?.DegPerS is { } v ? Result(await session.JogAsync(motor, v).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "jog: give {\"degPerS\": <number>}");
        });
        actions.MapPost("/motors/{motor}/setpoint", async (string motor, HttpRequest request) =>
        {
            var (body, problem) = await ApiBodies.Read<SetpointBody>(request, "setpoint").ConfigureAwait(false);
            return body?.Deg is { } v ? Result(await session.SetpointAsync(motor, v).ConfigureAwait(false)) : Error(StatusCodes.Status400BadRequest, problem ?? "setpoint: give {\"deg\": <number>}");
        });
        actions.MapPost("/motors/{motor}/release", async (string motor) => Result(await session.ReleaseAsync(motor).ConfigureAwait(false)));
        actions.MapPost("/motors/{motor}/home", async (string motor) => Result(await session.HomeAsync(motor).ConfigureAwait(false)));
        SurgeonEndpoints.Map(api, actions, session);
    }

    /// <summary>The console named by the request's <see cref="OperatorRole.ClientHeader"/> header, or null.</summary>
    public static string? ClientOf(HttpContext http)
    {
        var value = http.Request.Headers[OperatorRole.ClientHeader].ToString();
        return value.Length is > 0 and <= 64 ? value : null;
    }

    /// <summary>Lets <paramref name="group"/>'s requests through only from the operator's console (403 otherwise).</summary>
    public static RouteGroupBuilder OperatorOnly(RouteGroupBuilder group, OperatorRole role)
    {
        group.AddEndpointFilter(async (context, next) =>
            role.IsHeldBy(ClientOf(context.HttpContext))
                ? await next(context).ConfigureAwait(false)
                : Error(StatusCodes.Status403Forbidden, role.Holder is null
                    ? "this action needs the operator role: take it first (POST /api/operator)"
                    : "another console holds the operator role; this one watches"));
        return group;
    }

    private static object OperatorView(HttpContext http, OperatorRole role)
    {
        var holder = role.Holder;
        var client = ClientOf(http);
        return new { Held = holder is not null, You = client is not null && holder == client };
    }

    internal static IResult Json(object value) => Results.Json(value, ConsoleJson.Options);

    internal static IResult Error(int status, string message, IReadOnlyList<string>? details = null) =>
        Results.Json(new ApiError(message, details), ConsoleJson.Options, statusCode: status);

    internal static IResult Result(CommandResult result) => result.Outcome switch
    {
        CommandOutcome.Ok => Json(result),
        CommandOutcome.BadInput => Error(StatusCodes.Status400BadRequest, result.Message, result.Details),
        CommandOutcome.NotFound => Error(StatusCodes.Status404NotFound, result.Message, result.Details),
        CommandOutcome.Refused => Error(StatusCodes.Status422UnprocessableEntity, result.Message, result.Details),
        _ => Error(StatusCodes.Status503ServiceUnavailable, result.Message, result.Details),
    };
}
