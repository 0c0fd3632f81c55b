using System.Net;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Hosting;
using Microsoft.AspNetCore.Hosting.Server;
using Microsoft.AspNetCore.Hosting.Server.Features;
using Microsoft.Extensions.DependencyInjection;
using Microsoft.Extensions.Logging;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// The console's web server: the pages (the built front-end) and the JSON/WebSocket API over one
/// <see cref="IConsoleSession"/>, with access control (token on non-loopback binds, same-origin actions and
/// WebSockets, one operator at a time).
/// </summary>
public sealed class ConsoleServer : IAsyncDisposable
{
    private readonly WebApplication _app;

    private ConsoleServer(WebApplication app, string? token)
    {
        _app = app;
        Token = token;
    }

    /// <summary>The access token (null on a loopback bind without one).</summary>
    public string? Token { get; }

    /// <summary>The base URL, e.g. <c>http://127.0.0.1:5080/</c>.</summary>
    public Uri BaseUrl { get; private set; } = new("http://127.0.0.1/");

    /// <summary>The URL to open: the base URL, with the token when there is one.</summary>
    public Uri OpenUrl => Token is null ? BaseUrl : new Uri(BaseUrl, $"?token={Token}");

    /// <summary>The operator role.</summary>
    public OperatorRole Operator { get; private set; } = null!;

    /// <summary>
    /// Starts serving <paramref name="session"/> on <paramref name="bind"/>. A non-loopback bind without
    /// <paramref name="token"/> gets a generated one. With <paramref name="editor"/>, the graph editor's API too.
    /// <paramref name="first"/> (benchmarks, diagnostics) is the outermost middleware: it sees every request as soon as
    /// the server has read its headers, before access control and routing.
    /// </summary>
    public static async Task<ConsoleServer> StartAsync(IConsoleSession session, BindAddress bind, string? token, TimeProvider? time = null, Editor.GraphEditor? editor = null, Func<Microsoft.AspNetCore.Http.HttpContext, Microsoft.AspNetCore.Http.RequestDelegate, Task>? first = null)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(bind);
        if (token is { Length: < 8 })
        {
            throw new FormatException("--token: give at least 8 characters");
        }

        token ??= bind.IsLoopback ? null : AccessControl.NewToken();
        var builder = WebApplication.CreateSlimBuilder();
        builder.Logging.ClearProviders();
        builder.WebHost.ConfigureKestrel(k => k.Listen(bind.Address, bind.Port));
        var app = builder.Build();
        var server = new ConsoleServer(app, token) { Operator = new OperatorRole(time ?? TimeProvider.System) };
        var access = new AccessControl(token);
        if (first is not null)
        {
            app.Use(first);
        }

        app.UseWebSockets(new WebSocketOptions { KeepAliveInterval = TimeSpan.FromSeconds(15) });
        app.Use(access.Invoke);
        ApiEndpoints.Map(app, session, server.Operator);
        StreamEndpoint.Map(app, session);
        if (editor is not null)
        {
            GraphEndpoints.Map(app, editor, server.Operator);
        }

        var assets = new StaticAssets();
        app.MapGet("/{**path}", (Microsoft.AspNetCore.Http.HttpContext http, string? path) => assets.Serve(http, path));
        await app.StartAsync().ConfigureAwait(false);
        var address = app.Services.GetRequiredService<IServer>().Features.Get<IServerAddressesFeature>()!.Addresses.First();
        var port = new Uri(address).Port;
        var host = bind.Address.Equals(IPAddress.Any) || bind.Address.Equals(IPAddress.IPv6Any) ? Dns.GetHostName() : bind.ToString().Split(':')[0];
        if (bind.Address.AddressFamily == System.Net.Sockets.AddressFamily.InterNetworkV6 && !bind.Address.Equals(IPAddress.IPv6Any))
        {
            host = $"[{bind.Address}]";
        }

        server.BaseUrl = new Uri($"http://{host}:{port}/");
        return server;
    }

    /// <inheritdoc />
    public async ValueTask DisposeAsync()
    {
        await _app.StopAsync().ConfigureAwait(false);
        await _app.DisposeAsync().ConfigureAwait(false);
    }
}
