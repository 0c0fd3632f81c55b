using System.Reflection;
using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The built front-end (web/dist), embedded in this assembly as <c>wwwroot/...</c> resources: served by path, with
/// <c>index.html</c> for the root and for page routes. Hashed bundle files are cached for a year.
/// </summary>
internal sealed class StaticAssets
{
    private const string Prefix = "wwwroot/";
    private readonly Assembly _assembly = typeof(StaticAssets).Assembly;
    private readonly HashSet<string> _names;

    public StaticAssets()
    {
        _names = _assembly.GetManifestResourceNames().Where(n => n.StartsWith(Prefix, StringComparison.Ordinal)).ToHashSet(StringComparer.Ordinal);
    }

    /// <summary>True when the front-end was built into the assembly.</summary>
    public bool Available => _names.Contains(Prefix + "index.html");

    /// <summary>Serves <paramref name="path"/> (or index.html); 404 when neither exists.</summary>
    public async Task Serve(HttpContext context, string? path)
    {
        var name = Prefix + (string.IsNullOrEmpty(path) ? "index.html" : path);
        if (!_names.Contains(name))
        {
            if (Path.HasExtension(path))
            {
                context.Response.StatusCode = StatusCodes.Status404NotFound;
                return;
            }

            name = Prefix + "index.html";
            if (!_names.Contains(name))
            {
                context.Response.StatusCode = StatusCodes.Status404NotFound;
                await context.Response.WriteAsync("the console's front-end was not built (src/RobotControl.Console/web: npm install && npm run build)").ConfigureAwait(false);
                return;
            }
        }

        context.Response.ContentType = ContentType(name);
        context.Response.Headers.CacheControl = name.Contains("/assets/", StringComparison.Ordinal) ? "public, max-age=31536000, immutable" : "no-cache";
        await using var stream = _assembly.GetManifestResourceStream(name)!;
        await stream.CopyToAsync(context.Response.Body).ConfigureAwait(false);
    }

    private static string ContentType(string name) => Path.GetExtension(name) switch
    {
        ".html" => "text/html; charset=utf-8",
        ".js" => "text/javascript; charset=utf-8",
        ".css" => "text/css; charset=utf-8",
        ".svg" => "image/svg+xml",
        ".png" => "image/png",
        ".json" => "application/json",
        ".ico" => "image/x-icon",
        _ => "application/octet-stream",
    };
}
