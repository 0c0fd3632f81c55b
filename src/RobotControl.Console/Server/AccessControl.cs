using System.Security.Cryptography;
using System.Text;
using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// Who may talk to the console. With a token (required on any non-loopback bind) every request must carry it: as
/// <c>Authorization: Bearer &lt;token&gt;</c>, the <see cref="CookieName"/> cookie, or <c>?token=</c> on the page's
/// first load (which sets the cookie); otherwise 401. Requests that change something and WebSocket upgrades must come
/// from the console's own origin when the browser names one (403 otherwise), so another site cannot drive the robot
/// through a visitor's browser.
/// </summary>
internal sealed class AccessControl(string? token)
{
    /// <summary>The cookie that carries the token after the first load.</summary>
    public const string CookieName = "rc_token";

    private readonly byte[]? _token = token is null ? null : Encoding.UTF8.GetBytes(token);

    /// <summary>True when requests need the token.</summary>
    public bool RequiresToken => _token is not null;

    /// <summary>A new random token (URL-safe).</summary>
    public static string NewToken() => Convert.ToHexStringLower(RandomNumberGenerator.GetBytes(16));

    /// <summary>The middleware.</summary>
    public async Task Invoke(HttpContext context, RequestDelegate next)
    {
        var request = context.Request;
        if (_token is not null)
        {
            var fromQuery = request.Query["token"].ToString();
            var given = BearerToken(request) ?? (fromQuery.Length > 0 ? fromQuery : request.Cookies[CookieName]);
            if (given is null || !CryptographicOperations.FixedTimeEquals(Encoding.UTF8.GetBytes(given), _token))
            {
                await Refuse(context, StatusCodes.Status401Unauthorized, "this console needs its access token: open the URL it printed (with ?token=...) or send Authorization: Bearer <token>").ConfigureAwait(false);
                return;
            }

            if (fromQuery.Length > 0)
            {
                context.Response.Cookies.Append(CookieName, fromQuery, new CookieOptions { HttpOnly = true, SameSite = SameSiteMode.Strict, Path = "/" });
            }
        }

        var changes = !HttpMethods.IsGet(request.Method) && !HttpMethods.IsHead(request.Method);
        if ((changes || context.WebSockets.IsWebSocketRequest) && !SameOrigin(request))
        {
            await Refuse(context, StatusCodes.Status403Forbidden, $"origin '{request.Headers.Origin}' is not this console's ({request.Scheme}://{request.Host})").ConfigureAwait(false);
            return;
        }

        await next(context).ConfigureAwait(false);
    }

    private static string? BearerToken(HttpRequest request)
    {
        var header = request.Headers.Authorization.ToString();
        return header.StartsWith("Bearer ", StringComparison.Ordinal) ? header["Bearer ".Length..].Trim() : null;
    }

    private static bool SameOrigin(HttpRequest request)
    {
        var origin = request.Headers.Origin.ToString();
        return origin.Length == 0 || string.Equals(origin, $"{request.Scheme}://{request.Host}", StringComparison.OrdinalIgnoreCase);
    }

    private static Task Refuse(HttpContext context, int status, string message)
    {
        context.Response.StatusCode = status;
        return context.Response.WriteAsJsonAsync(new ApiError(message));
    }
}

/// <summary>The body of every error response.</summary>
/// <param name="Error">One line saying what was wrong.</param>
/// <param name="Details">Further lines, if any.</param>
public sealed record ApiError(string Error, IReadOnlyList<string>? Details = null);
