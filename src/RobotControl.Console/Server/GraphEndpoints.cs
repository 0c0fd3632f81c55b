using System.Text.Json;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Editor;

namespace RobotControl.WebConsole.Server;

/// <summary>The graph editor's API under <c>/api/editor</c> (see docs/console.md). Saving, start and stop need the operator role; the graph-file work is rate-limited per client.</summary>
internal static class GraphEndpoints
{
    public static void Map(IEndpointRouteBuilder app, GraphEditor editor, OperatorRole role)
    {
        var api = app.MapGroup("/api/editor");
        api.MapGet("/catalog", (string? robot) => editor.Catalog(robot, out var refusal) is { } catalog
            ? ApiEndpoints.Json(catalog)
            : ApiEndpoints.Error(StatusCodes.Status400BadRequest, refusal)).RequireRateLimiting(RateLimits.Editor);
        api.MapGet("/graphs", () => ApiEndpoints.Json(new { Folder = Path.GetFileName(editor.Folder.Root), Graphs = editor.Folder.List() }));
        // Route values keep %2F escaped: unescape, so "sub%2Fx.json" is the refused "sub/x.json", not a file of that name.
        api.MapGet("/graphs/{name}", (string name) => editor.Read(Uri.UnescapeDataString(name), out var refusal) is { } text
            ? Results.Text(text, "application/json")
            : ApiEndpoints.Error(refusal.Contains("no such file", StringComparison.Ordinal) ? StatusCodes.Status404NotFound : StatusCodes.Status400BadRequest, refusal));
        api.MapPost("/check", async (HttpRequest request) =>
        {
            var (body, problem) = await ReadGraph(request, "check").ConfigureAwait(false);
            return body is null ? Bad(problem)
                : editor.Check(body.Name, body.Graph!.Value.GetRawText(), out var refusal) is { } check ? ApiEndpoints.Json(check)
                : ApiEndpoints.Error(StatusCodes.Status400BadRequest, refusal);
        }).RequireRateLimiting(RateLimits.Editor);
        api.MapGet("/run", () => ApiEndpoints.Json(editor.Runner.View));

        // Stopping the run (motors off) needs no role: stopping is never a privilege.
        api.MapPost("/stop", async () => ApiEndpoints.Json(await editor.Runner.StopAsync().ConfigureAwait(false))).RequireRateLimiting(RateLimits.Editor);

        // Writing a file or switching the session: the operator's.
        var actions = ApiEndpoints.OperatorOnly(api.MapGroup(string.Empty), role);
        actions.MapPut("/graphs/{name}", async (string name, HttpRequest request) =>
        {
            var (body, problem) = await ReadGraph(request, "save").ConfigureAwait(false);
            name = Uri.UnescapeDataString(name);
            return body is null ? Bad(problem) : Refusing(editor.Save(name, body.Graph!.Value.GetRawText(), out var refusal), refusal, $"saved {name}", name);
        }).RequireRateLimiting(RateLimits.Editor);
        actions.MapPost("/start", async (HttpRequest request) =>
        {
            var (body, problem) = await ReadGraph(request, "start").ConfigureAwait(false);
            if (body is null)
            {
                return Bad(problem);
            }

            var name = body.Name ?? string.Empty;
            var problems = editor.Save(name, body.Graph!.Value.GetRawText(), out var refusal);
            if (problems is null || problems.Count > 0)
            {
                return Refusing(problems, refusal, string.Empty, name);
            }

            var run = await editor.Runner.StartAsync(editor.Folder.Resolve(name, out _)!).ConfigureAwait(false);
            return run.Running ? ApiEndpoints.Json(run) : ApiEndpoints.Error(StatusCodes.Status422UnprocessableEntity, run.Problem ?? $"{name} did not start");
        }).RequireRateLimiting(RateLimits.Editor);
    }

    private static IResult Bad(string? problem) => ApiEndpoints.Error(StatusCodes.Status400BadRequest, problem ?? "give {\"graph\": {...}}");

    /// <summary>200 with <paramref name="done"/> when there are no problems, 422 listing them (nothing written) otherwise.</summary>
    private static IResult Refusing(IReadOnlyList<ProblemView>? problems, string refusal, string done, string name) =>
        problems is null ? ApiEndpoints.Error(StatusCodes.Status400BadRequest, refusal)
        : problems.Count == 0 ? ApiEndpoints.Json(new { Message = done, Problems = problems })
        : Results.Json(
            new { Error = $"{name}: the graph has {problems.Count} problem{(problems.Count == 1 ? "" : "s")}; fix {(problems.Count == 1 ? "it" : "them")} first", Details = problems.Select(p => $"{p.Path}: {p.Message}"), Problems = problems },
            ConsoleJson.Options,
            statusCode: StatusCodes.Status422UnprocessableEntity);

    private static async Task<(GraphBody? Body, string? Problem)> ReadGraph(HttpRequest request, string what)
    {
        var (body, problem) = await ApiBodies.Read<GraphBody>(request, what).ConfigureAwait(false);
        return body?.Graph is { ValueKind: JsonValueKind.Object } ? (body, null) : (null, problem ?? $"{what}: give {{\"name\": \"<file>.json\", \"graph\": {{...}}}}");
    }
}

/// <summary>A graph sent by the editor: the file it is (or will be) and its content.</summary>
internal sealed record GraphBody(string? Name, JsonElement? Graph);
