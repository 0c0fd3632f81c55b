using System.Net;
using System.Net.Http.Headers;
using System.Net.Http.Json;
using System.Text.Json;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>
/// Stopping is never a privilege, and nothing else is granted to a request that is not from the console's own page:
/// E-STOP from a client with no token and no role, and a few hundred requests with random Host, Origin and token where
/// only an allow-listed Host with its own (or no) Origin and the right token takes the operator role, and every E-STOP
/// with an allow-listed Host stops.
/// </summary>
public sealed class HostOriginPropertyTests
{
    [Fact]
    public async Task E_stop_is_accepted_without_token_or_role()
    {
        using var session = ConsoleFixture.VirtualSession();
        await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
        using var anonymous = new HttpClient { BaseAddress = server.BaseUrl }; // no token, no X-Console-Client, no role

        var response = await anonymous.PostAsync("api/estop", null);

        Assert.Equal(HttpStatusCode.OK, response.StatusCode);
        Assert.Contains("run level E_STOP", (await response.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("message").GetString(), StringComparison.Ordinal);
        Assert.Equal("E_STOP", session.Status.RobotState);
        Assert.Equal(HttpStatusCode.Unauthorized, (await anonymous.GetAsync("api/status")).StatusCode); // and nothing else
    }

    [Fact]
    public async Task E_stop_is_outside_the_rate_limits_and_the_stream_cap()
    {
        using var session = ConsoleFixture.VirtualSession();
        var spent = new ConsoleRateLimits(new RateLimit(1, 1, TimeSpan.FromMinutes(10)), new RateLimit(1, 1, TimeSpan.FromMinutes(10)));
        await using var server = await ConsoleServer.StartAsync(session, new ConsoleServerOptions { Bind = BindAddress.Parse("127.0.0.1:0"), RateLimits = spent, MaxStreams = 1 });
        using var client = ConsoleFixture.Client(server, "busy-client");
        Assert.Equal(HttpStatusCode.Forbidden, (await client.PostAsync("api/controllers/1/reload", null)).StatusCode);
        Assert.Equal(HttpStatusCode.TooManyRequests, (await client.PostAsync("api/controllers/1/reload", null)).StatusCode); // its bucket is empty
        using var stream = new System.Net.WebSockets.ClientWebSocket();
        await stream.ConnectAsync(new Uri($"ws://{server.BaseUrl.Authority}/api/stream?token={server.Token}"), CancellationToken.None); // the one stream place taken

        var response = await client.PostAsync("api/estop", null);

        Assert.Equal(HttpStatusCode.OK, response.StatusCode);
        Assert.Equal("E_STOP", session.Status.RobotState);
    }

    [Fact]
    public async Task Only_an_allowed_host_with_its_own_origin_and_the_token_changes_anything_and_e_stop_always_stops()
    {
        using var session = ConsoleFixture.VirtualSession();
        await using var server = await ConsoleServer.StartAsync(session, new ConsoleServerOptions { Bind = BindAddress.Parse("127.0.0.1:0"), AllowedHosts = ["robot.lab"] });
        var port = server.BaseUrl.Port;
        string[] allowed = [$"127.0.0.1:{port}", $"localhost:{port}", $"LOCALHOST:{port}", $"[::1]:{port}", $"robot.lab:{port}", "robot.lab", "127.0.0.1"];
        string[] foreign = [$"evil.example:{port}", $"127.0.0.1.evil.example:{port}", $"localhost.evil.example:{port}", $"robot.lab.evil.example:{port}", $"10.1.2.3:{port}", "evil.example", $"xn--lcalhost-3ya:{port}"];
        var random = new Random(29);
        using var http = new HttpClient { BaseAddress = server.BaseUrl };
        var changed = 0;
        var stops = 0;
        for (var i = 0; i < 300; i++)
        {
            var hostAllowed = random.Next(2) == 0;
            var host = hostAllowed ? allowed[random.Next(allowed.Length)] : foreign[random.Next(foreign.Length)];
            var (origin, ownOrigin) = random.Next(5) switch
            {
                0 => (null, true),
                1 => ($"http://{host}", true),
                2 => ($"http://{foreign[random.Next(foreign.Length)]}", false),
                3 => ($"https://{host}", false),
                _ => ("null", false),
            };
            var (token, rightToken) = random.Next(3) switch
            {
                0 => (server.Token, true),
                1 => ((string?)null, false),
                _ => ("0123456789abcdef0123456789abcdef", false),
            };
            var estop = random.Next(4) == 0;
            var client = $"client-{i}";
            using var request = new HttpRequestMessage(HttpMethod.Post, estop ? "api/estop" : "api/operator");
            request.Headers.Host = host;
            request.Headers.Add(OperatorRole.ClientHeader, client);
            if (origin is not null)
            {
                request.Headers.Add("Origin", origin);
            }

            if (token is not null)
            {
                request.Headers.Authorization = new AuthenticationHeaderValue("Bearer", token);
            }

            var response = await http.SendAsync(request);
            var what = $"case {i}: {(estop ? "E-STOP" : "take the operator role")} with Host '{host}', Origin '{origin}', {(rightToken ? "the token" : token is null ? "no token" : "a wrong token")}: {(int)response.StatusCode}";
            if (estop)
            {
                Assert.True(hostAllowed == (response.StatusCode == HttpStatusCode.OK), what);
                stops += hostAllowed ? 1 : 0;
                continue;
            }

            var granted = hostAllowed && ownOrigin && rightToken;
            Assert.True(granted == (response.StatusCode == HttpStatusCode.OK), what);
            Assert.True(granted == (server.Operator.Holder == client), what);
            changed += granted ? 1 : 0;
            if (server.Operator.Holder is { } holder)
            {
                server.Operator.Release(holder);
            }
        }

        Assert.Equal("E_STOP", session.Status.RobotState);
        Assert.True(changed > 10 && stops > 10, $"{changed} granted, {stops} stops: the cases should cover both");
    }
}
