using System.Security.Cryptography;
using System.Text;
using Microsoft.AspNetCore.Http;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// Who may talk to the console, checked in this order for every request (docs/console.md, "Security"):
/// <list type="number">
/// <item>the <c>Host</c> header must be one of <see cref="HostAllowList"/>'s (403 otherwise: DNS rebinding);</item>
/// <item><c>POST /api/estop</c> is answered right here, before the token, the origin, the rate limits and routing:
/// stopping is never a privilege and never waits (it is noted in the session's recording after it is answered);</item>
/// <item>every other <c>/api</c> request needs the session's token, as <c>Authorization: Bearer &lt;token&gt;</c> or
/// <c>?token=</c> (the WebSocket; 401 otherwise). The pages themselves (no session data) are served without it: the
/// page reads the token from the URL the console printed;</item>
/// <item>requests that change something and WebSocket upgrades must come from the console's own origin when the
/// browser names one (403 otherwise).</item>
/// </list>
/// Every response gets the security headers (<see cref="SecurityHeaders"/>), every API answer the server's run
/// (<see cref="ConsoleServer.InstanceHeader"/>), and an unexpected failure is a JSON 500
/// with one line, never an empty body or a stack trace.
/// </summary>
internal sealed class AccessControl(string token, HostAllowList hosts, IConsoleSession session, OperatorRole role, string instance)
{
    private readonly byte[] _token = Encoding.UTF8.GetBytes(token);

    /// <summary>A new random token (URL-safe).</summary>
    public static string NewToken() => Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(16));

    /// <summary>The middleware.</summary>
    public async Task Invoke(HttpContext context, RequestDelegate next)
    {
        var request = context.Request;
        var api = request.Path.StartsWithSegments("/api", StringComparison.Ordinal);
        SecurityHeaders.Add(context.Response, request, api);
        if (api)
        {
            context.Response.Headers[ConsoleServer.InstanceHeader] = instance; // the page tells a restarted server by it
        }
        if (!hosts.Allows(request.Host))
        {
            await Refuse(context, StatusCodes.Status403Forbidden, $"host '{request.Host}' is not a name of this console (add it with --allowed-host)").ConfigureAwait(false);
            return;
        }

        if (HttpMethods.IsPost(request.Method) && request.Path.Equals("/api/estop", StringComparison.Ordinal))
        {
            // Any console, watching or operating, with or without the token: stopping is never a privilege.
            var answer = ApiEndpoints.Result(await session.EmergencyStopAsync().ConfigureAwait(false));
            await answer.ExecuteAsync(context).ConfigureAwait(false);
            session.NoteCommand(CommandWitness.Who(context, role), $"POST /api/estop -> {CommandWitness.Answer(answer)}"); // after the stop, never before
            return;
        }

        if (api && !HasToken(request))
        {
            await Refuse(context, StatusCodes.Status401Unauthorized, "this console needs its access token: open the URL it printed (with ?token=...) or send Authorization: Bearer <token>").ConfigureAwait(false);
            return;
        }

        var changes = !HttpMethods.IsGet(request.Method) && !HttpMethods.IsHead(request.Method);
        if ((changes || context.WebSockets.IsWebSocketRequest) && !SameOrigin(request))
        {
            await Refuse(context, StatusCodes.Status403Forbidden, $"origin '{request.Headers.Origin}' is not this console's ({request.Scheme}://{request.Host})").ConfigureAwait(false);
            return;
        }

        try
        {
            await next(context).ConfigureAwait(false);
        }
        catch (Exception ex) when (!context.Response.HasStarted && ex is not OperationCanceledException)
        {
            await Refuse(context, StatusCodes.Status500InternalServerError, $"{request.Method} {request.Path}: the console failed ({ex.GetType().Name}); nothing was changed by this request's answer").ConfigureAwait(false);
        }
    }

    private bool HasToken(HttpRequest request)
    {
        var header = request.Headers.Authorization.ToString();
        var given = header.StartsWith("Bearer ", StringComparison.Ordinal) ? header["Bearer ".Length..].Trim() : request.Query["token"].ToString();
        return given.Length > 0 && CryptographicOperations.FixedTimeEquals(Encoding.UTF8.GetBytes(given), _token);
    }

    private static bool SameOrigin(HttpRequest request)
    {
        var origin = request.Headers.Origin.ToString();
        return origin.Length == 0 || string.Equals(origin, $"{request.Scheme}://{request.Host}", StringComparison.OrdinalIgnoreCase);
    }

    /// <summary>Answers <paramref name="status"/> with <paramref name="message"/> as the API's error body.</summary>
    public static Task Refuse(HttpContext context, int status, string message)
    {
        context.Response.StatusCode = status;
        return context.Response.WriteAsJsonAsync(new ApiError(message), ConsoleJson.Options);
    }
}

/// <summary>The body of every error response.</summary>
/// <param name="Error">One line saying what was wrong.</param>
/// <param name="Details">Further lines, if any.</param>
public sealed record ApiError(string Error, IReadOnlyList<string>? Details = null);
