using System.Security.Cryptography.X509Certificates;
using Microsoft.AspNetCore.Http;

namespace RobotControl.WebConsole.Server;

/// <summary>How the console serves (see docs/console.md, "Security").</summary>
public sealed record ConsoleServerOptions
{
    /// <summary>The address and port to listen on.</summary>
    public required BindAddress Bind { get; init; }

    /// <summary>The session's access token (8 characters or more); null: a random one.</summary>
    public string? Token { get; init; }

    /// <summary>Host names the console answers to besides the loopback names, the bind address and this machine's (<c>--allowed-host</c>).</summary>
    public IReadOnlyList<string> AllowedHosts { get; init; } = [];

    /// <summary>The certificate to serve HTTPS with (<c>--https-cert</c>); null: plain HTTP.</summary>
    public X509Certificate2? Certificate { get; init; }

    /// <summary>Per-client request rates of the expensive endpoints.</summary>
    public ConsoleRateLimits RateLimits { get; init; } = ConsoleRateLimits.Default;

    /// <summary>The most WebSocket streams served at once; more are refused with 503.</summary>
    public int MaxStreams { get; init; } = 16;

    /// <summary>Frames waiting for one stream client at most; older ones are dropped when it falls behind.</summary>
    public int StreamQueueFrames { get; init; } = 4;

    /// <summary>The clock of the operator role's lease.</summary>
    public TimeProvider Time { get; init; } = TimeProvider.System;

    /// <summary>The graph editor, whose API is served too; null: none.</summary>
    public Editor.GraphEditor? Editor { get; init; }

    /// <summary>The outermost middleware (benchmarks, diagnostics): sees every request before access control and routing.</summary>
    public Func<HttpContext, RequestDelegate, Task>? First { get; init; }
}

/// <summary>
/// Token buckets per client (the <c>X-Console-Client</c> header, else the remote address): <paramref name="Bus"/> for
/// requests that cost bus time (re-read parameters, discover, reboot, parameter writes), <paramref name="Editor"/> for
/// the editor's checks, catalog, saves, starts and stops. Beyond them: 429 with <c>Retry-After</c>.
/// </summary>
/// <param name="Bus">Bus work.</param>
/// <param name="Editor">Graph-file work.</param>
public sealed record ConsoleRateLimits(RateLimit Bus, RateLimit Editor)
{
    /// <summary>8 bus requests at once, 2 more per second; 20 editor requests at once, 10 more per second.</summary>
    public static ConsoleRateLimits Default { get; } = new(new RateLimit(8, 2, TimeSpan.FromSeconds(1)), new RateLimit(20, 10, TimeSpan.FromSeconds(1)));
}

/// <summary>A token bucket: <paramref name="Burst"/> requests at once, <paramref name="PerPeriod"/> more each <paramref name="Period"/>.</summary>
/// <param name="Burst">The bucket's size.</param>
/// <param name="PerPeriod">Tokens added each period.</param>
/// <param name="Period">The replenishment period.</param>
public sealed record RateLimit(int Burst, int PerPeriod, TimeSpan Period);
