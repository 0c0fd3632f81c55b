using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The headers every response carries: no framing by any site (<c>frame-ancestors 'none'</c>, <c>X-Frame-Options:
/// DENY</c>), scripts, styles and connections from the console itself only, no MIME sniffing, no referrer, and
/// <c>Cache-Control: no-store</c> on the API.
/// </summary>
internal static class SecurityHeaders
{
    /// <summary>Sets the headers on <paramref name="response"/>; <paramref name="api"/>: an API response (never cached).</summary>
    public static void Add(HttpResponse response, HttpRequest request, bool api)
    {
        var headers = response.Headers;
        var ws = request.IsHttps ? "wss" : "ws";
        headers.ContentSecurityPolicy = $"default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; media-src 'self' blob: mediastream:; connect-src 'self' {ws}://{request.Host}; worker-src 'self' blob:; object-src 'none'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";
        headers.XFrameOptions = "DENY";
        headers.XContentTypeOptions = "nosniff";
        headers["Referrer-Policy"] = "no-referrer";
        if (api)
        {
            headers.CacheControl = "no-store";
        }
    }
}
