using System.Net;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.AspNetCore.Http;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The console's web server: the pages (the built front-end) and the JSON/WebSocket API over one
/// <see cref="IConsoleSession"/>, behind <see cref="AccessControl"/> (host allow-list, the session's token, same-origin
/// actions and WebSockets), one operator at a time, per-client rate limits on expensive endpoints and a cap on streams.
/// </summary>
public sealed class ConsoleServer : IAsyncDisposable
{
    private readonly WebApplication _app;

    private ConsoleServer(WebApplication app, string token, OperatorRole role)
    {
        _app = app;
        Token = token;
        Operator = role;
    }

    /// <summary>The name of the header that carries <see cref="Instance"/> on every API answer.</summary>
    public const string InstanceHeader = "X-Console-Instance";

    /// <summary>
    /// This run of the console server: random, set once at its start, on every API answer (<see cref="InstanceHeader"/>),
    /// in <c>/api/status</c> and in the stream's answer to a subscription. A page that sees it change knows the server
    /// was restarted and starts again (docs/console.md, "After a restart").
    /// </summary>
    public string Instance { get; } = Convert.ToHexStringLower(System.Security.Cryptography.RandomNumberGenerator.GetBytes(8));

    /// <summary>The session's access token (given or generated).</summary>
    public string Token { get; }

    /// <summary>The base URL, e.g. <c>http://127.0.0.1:5080/</c>.</summary>
    public Uri BaseUrl { get; private set; } = new("http://127.0.0.1/");

    /// <summary>The URL to open: the base URL with <c>?token=</c> (the page keeps the token and strips it from the address bar).</summary>
    public Uri OpenUrl => new(BaseUrl, $"?token={Token}");

    /// <summary>The operator role.</summary>
    public OperatorRole Operator { get; }

    /// <summary>Starts serving <paramref name="session"/> on <paramref name="bind"/> (see <see cref="StartAsync(IConsoleSession, ConsoleServerOptions)"/>).</summary>
    public static Task<ConsoleServer> StartAsync(IConsoleSession session, BindAddress bind, string? token, TimeProvider? time = null, Editor.GraphEditor? editor = null, Func<HttpContext, RequestDelegate, Task>? first = null) =>
        StartAsync(session, new ConsoleServerOptions { Bind = bind, Token = token, Time = time ?? TimeProvider.System, Editor = editor, First = first });

    /// <summary>
    /// Starts serving <paramref name="session"/> as <paramref name="options"/> say: with the given token or a random
    /// one, HTTPS when a certificate is given, the graph editor's API when there is an editor.
    /// </summary>
    /// <exception cref="FormatException">A token shorter than 8 characters.</exception>
    public static async Task<ConsoleServer> StartAsync(IConsoleSession session, ConsoleServerOptions options)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(options);
        if (options.Token is { Length: < 8 })
        {
            throw new FormatException("--token: give at least 8 characters");
        }

        var bind = options.Bind;
        var token = options.Token ?? AccessControl.NewToken();
        var builder = WebApplication.CreateSlimBuilder();
        builder.Logging.ClearProviders();
        builder.WebHost.ConfigureKestrel(k =>
        {
            k.Limits.MaxRequestBodySize = ApiBodies.MaxBytes;
            k.Listen(bind.Address, bind.Port, listen =>
            {
                if (options.Certificate is { } certificate)
                {
                    listen.UseHttps(certificate);
                }
            });
        });
        RateLimits.Add(builder.Services, options.RateLimits);
        var app = builder.Build();
        var server = new ConsoleServer(app, token, new OperatorRole(options.Time));
        var host = PrintedHost(bind);
        var access = new AccessControl(token, new HostAllowList(bind, options.AllowedHosts, host), session, server.Operator, server.Instance);
        if (options.First is not null)
        {
            app.Use(options.First);
        }

        app.UseWebSockets(new WebSocketOptions { KeepAliveInterval = TimeSpan.FromSeconds(15) }); // accepts nothing itself: lets access control tell an upgrade
        app.Use(access.Invoke); // E-STOP is answered in here, before the rate limits and routing
        app.UseRouting();
        app.UseRateLimiter();
        ApiEndpoints.Map(app, session, server.Operator, server.Instance);
        StreamEndpoint.Map(app, session, options.MaxStreams, options.StreamQueueFrames, server.Instance);
        if (session is Replay.ReplaySession replay)
        {
            Replay.ReplayEndpoints.Map(app, replay);
        }

        if (session is BringUp.BringUpSession bringUp)
        {
            BringUp.BringUpEndpoints.Map(app, bringUp, server.Operator);
        }

        if (options.Editor is not null)
        {
            GraphEndpoints.Map(app, options.Editor, server.Operator);
        }

        app.Map("/api/{**rest}", (HttpRequest request) => ApiEndpoints.Error(StatusCodes.Status404NotFound, $"{request.Method} {request.Path}: no such API endpoint (see docs/console.md)"));
        var assets = new StaticAssets();
        app.MapGet("/{**path}", (HttpContext http, string? path) => assets.Serve(http, path));
        await app.StartAsync().ConfigureAwait(false);
        var address = app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First();
        var port = new Uri(address).Port;
        var scheme = options.Certificate is null ? "http" : "https";
        server.BaseUrl = new Uri($"{scheme}://{(host.Contains(':', StringComparison.Ordinal) ? $"[{host}]" : host)}:{port}/");
        return server;
    }

    /// <summary>The host of the printed URL: this machine's name on a wildcard bind, the bind address otherwise.</summary>
    private static string PrintedHost(BindAddress bind) =>
        bind.Address.Equals(IPAddress.Any) || bind.Address.Equals(IPAddress.IPv6Any) ? Dns.GetHostName() : bind.Address.ToString();

    /// <inheritdoc />
    public async ValueTask DisposeAsync()
    {
        await _app.StopAsync().ConfigureAwait(false);
        await _app.DisposeAsync().ConfigureAwait(false);
    }
}
