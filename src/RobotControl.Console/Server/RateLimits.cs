using System.Globalization;
using System.Threading.RateLimiting;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.RateLimiting;
using Microsoft.Extensions.DependencyInjection;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// ASP.NET Core's rate limiting on the expensive endpoints, one token bucket per client and policy
/// (<see cref="ConsoleRateLimits"/>); a refused request is 429 with <c>Retry-After</c> and the API's error body. The
/// emergency stop never gets here (<see cref="AccessControl"/> answers it first).
/// </summary>
internal static class RateLimits
{
    /// <summary>Bus work: re-read parameters, discover, reboot, parameter writes.</summary>
    public const string Bus = "bus";

    /// <summary>The editor's graph-file work: check, catalog, save, start, stop.</summary>
    public const string Editor = "editor";

    public static void Add(IServiceCollection services, ConsoleRateLimits limits) =>
        services.AddRateLimiter(options =>
        {
            options.RejectionStatusCode = StatusCodes.Status429TooManyRequests;
            options.AddPolicy(Bus, http => Bucket(http, Bus, limits.Bus));
            options.AddPolicy(Editor, http => Bucket(http, Editor, limits.Editor));
            options.OnRejected = (context, token) =>
            {
                var retry = context.Lease.TryGetMetadata(MetadataName.RetryAfter, out var after) ? Math.Max(1, (int)Math.Ceiling(after.TotalSeconds)) : 1;
                context.HttpContext.Response.Headers.RetryAfter = retry.ToString(CultureInfo.InvariantCulture);
                return new ValueTask(context.HttpContext.Response.WriteAsJsonAsync(
                    new ApiError($"{context.HttpContext.Request.Path}: too many requests from this console; try again in {retry} s"), ConsoleJson.Options, token));
            };
        });

    private static RateLimitPartition<string> Bucket(HttpContext http, string policy, RateLimit limit) =>
        RateLimitPartition.GetTokenBucketLimiter($"{policy}|{ApiEndpoints.ClientOf(http) ?? http.Connection.RemoteIpAddress?.ToString()}", _ => new TokenBucketRateLimiterOptions
        {
            TokenLimit = limit.Burst,
            TokensPerPeriod = limit.PerPeriod,
            ReplenishmentPeriod = limit.Period,
            QueueLimit = 0,
            AutoReplenishment = true,
        });
}
