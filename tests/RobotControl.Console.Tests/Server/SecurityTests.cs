using System.Net;
using System.Net.Http.Json;
using System.Net.WebSockets;
using System.Text.Json;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

/// <summary>
/// Issue 29, class 4 and 5 on the shared console: the Host allow-list (DNS rebinding), the token on loopback, watchers
/// read-only, security headers, JSON 404 and 400, rate limits with Retry-After, the cap on streams.
/// </summary>
[Collection(ConsoleCollection.Name)]
public sealed class SecurityTests(ConsoleFixture console)
{
    [Fact]
    public async Task A_rebound_host_name_is_refused_even_with_the_token_and_its_own_origin()
    {
        console.ReleaseOperator();
        using var http = console.Client("rebinder");
        async Task<HttpResponseMessage> Send(HttpMethod method, string path, object? body = null)
        {
            using var request = new HttpRequestMessage(method, path) { Content = body is null ? null : JsonContent.Create(body) };
            request.Headers.Host = $"evil.example:{console.Server.BaseUrl.Port}";
            request.Headers.Add("Origin", $"http://evil.example:{console.Server.BaseUrl.Port}");
            return await http.SendAsync(request);
        }

        var claim = await Send(HttpMethod.Post, "api/operator");
        Assert.Equal(HttpStatusCode.Forbidden, claim.StatusCode);
        Assert.Contains("host 'evil.example:", (await claim.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString(), StringComparison.Ordinal);
        Assert.Equal(HttpStatusCode.Forbidden, (await Send(HttpMethod.Post, "api/pedal", new { down = true })).StatusCode);
        Assert.Equal(HttpStatusCode.Forbidden, (await Send(HttpMethod.Post, "api/motors/right.elbow/jog", new { degPerS = 5 })).StatusCode);
        Assert.Equal(HttpStatusCode.Forbidden, (await Send(HttpMethod.Get, "api/status")).StatusCode);
        Assert.Equal(HttpStatusCode.Forbidden, (await Send(HttpMethod.Get, "/")).StatusCode);

        Assert.Null(console.Server.Operator.Holder);
        Assert.False((await ConsoleFixture.Motor(http, "right.elbow")).GetProperty("manual").GetBoolean());
        Assert.Equal("PEDAL_UP", console.Session.Status.RobotState);
    }

    [Fact]
    public async Task Operator_commands_need_the_token_and_work_with_it()
    {
        console.ReleaseOperator();
        using var holder = await console.Operator("token-holder");
        foreach (var token in new string?[] { null, "wrong-token-0123456789" })
        {
            using var http = new HttpClient { BaseAddress = console.Server.BaseUrl };
            http.DefaultRequestHeaders.Add(OperatorRole.ClientHeader, "token-holder"); // even naming the operator's console
            if (token is not null)
            {
                http.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", token);
            }

            Assert.Equal(HttpStatusCode.Unauthorized, (await http.PostAsync("api/motors/right.elbow/release", null)).StatusCode);
            Assert.Equal(HttpStatusCode.Unauthorized, (await http.PostAsJsonAsync("api/pedal", new { down = true })).StatusCode);
            Assert.Equal(HttpStatusCode.Unauthorized, (await http.PostAsync("api/operator", null)).StatusCode);
        }

        Assert.Equal(HttpStatusCode.OK, (await holder.PostAsync("api/motors/right.elbow/release", null)).StatusCode);
        Assert.Equal("PEDAL_UP", console.Session.Status.RobotState);
        console.ReleaseOperator();
    }

    [Fact]
    public async Task A_watcher_cannot_re_read_parameters_or_write_them()
    {
        using var holder = await console.Operator("reads-operator");
        using var watcher = console.Client("reads-watcher");
        var id = (await watcher.GetFromJsonAsync<JsonElement>("api/controllers"))[0].GetProperty("id").GetInt32();

        var reload = await watcher.PostAsync($"api/controllers/{id}/reload", null);
        Assert.Equal(HttpStatusCode.Forbidden, reload.StatusCode);
        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PutAsJsonAsync("api/motors/right.elbow/parameters/kp", new { value = 1 })).StatusCode);
        console.ReleaseOperator();
    }

    [Fact]
    public async Task Every_response_carries_the_security_headers_and_the_api_is_never_cached()
    {
        using var http = console.Client("headers");
        foreach (var path in new[] { "/", "api/status", "api/nosuch" })
        {
            var response = await http.GetAsync(path);
            Assert.Contains("frame-ancestors 'none'", response.Headers.GetValues("Content-Security-Policy").Single(), StringComparison.Ordinal);
            Assert.Equal("DENY", response.Headers.GetValues("X-Frame-Options").Single());
            Assert.Equal("nosniff", response.Headers.GetValues("X-Content-Type-Options").Single());
            Assert.Equal("no-referrer", response.Headers.GetValues("Referrer-Policy").Single());
            Assert.Equal(path.StartsWith("api/", StringComparison.Ordinal), response.Headers.CacheControl?.NoStore == true);
        }
    }

    [Theory]
    [InlineData("GET", "api/nosuch")]
    [InlineData("POST", "api/motors/right.elbow/nosuch")]
    [InlineData("GET", "api/estop")]
    public async Task An_unknown_api_path_is_a_json_404(string method, string path)
    {
        using var http = console.Client("unknown");
        var response = await http.SendAsync(new HttpRequestMessage(new HttpMethod(method), path));
        Assert.Equal(HttpStatusCode.NotFound, response.StatusCode);
        Assert.Equal("application/json", response.Content.Headers.ContentType?.MediaType);
        Assert.Contains("no such API endpoint", (await response.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString(), StringComparison.Ordinal);
    }

    [Fact]
    public async Task An_over_long_module_name_is_a_json_400_naming_the_field_and_the_limit()
    {
        using var http = await console.Operator("long-name");
        var id = (await http.GetFromJsonAsync<JsonElement>("api/controllers"))[0].GetProperty("id").GetInt32();
        var response = await http.PutAsJsonAsync($"api/controllers/{id}/name", new { name = new string('x', 5000) });
        Assert.Equal(HttpStatusCode.BadRequest, response.StatusCode);
        Assert.Equal("name: give 1..40 printable characters", (await response.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString());
        console.ReleaseOperator();
    }

    [Fact]
    public async Task Beyond_its_rate_a_client_gets_429_with_retry_after_and_other_clients_do_not()
    {
        var limits = new ConsoleRateLimits(new RateLimit(2, 1, TimeSpan.FromMinutes(10)), ConsoleRateLimits.Default.Editor);
        await using var server = await ConsoleServer.StartAsync(console.Session, new ConsoleServerOptions { Bind = BindAddress.Parse("127.0.0.1:0"), RateLimits = limits });
        using var watcher = ConsoleFixture.Client(server, "eager-watcher");
        using var other = ConsoleFixture.Client(server, "other-watcher");

        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PostAsync("api/controllers/1/reload", null)).StatusCode);
        Assert.Equal(HttpStatusCode.Forbidden, (await watcher.PostAsync("api/controllers/1/reload", null)).StatusCode);
        var limited = await watcher.PostAsync("api/controllers/1/reload", null);

        Assert.Equal(HttpStatusCode.TooManyRequests, limited.StatusCode);
        Assert.True(limited.Headers.RetryAfter?.Delta > TimeSpan.Zero, $"Retry-After: {limited.Headers.RetryAfter}");
        Assert.Contains("too many requests from this console", (await limited.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString(), StringComparison.Ordinal);
        Assert.Equal(HttpStatusCode.Forbidden, (await other.PostAsync("api/controllers/1/reload", null)).StatusCode); // its own bucket
        Assert.Equal(HttpStatusCode.OK, (await watcher.GetAsync("api/status")).StatusCode); // reads are not limited
    }

    [Fact]
    public async Task Streams_beyond_the_cap_are_refused_with_503()
    {
        await using var server = await ConsoleServer.StartAsync(console.Session, new ConsoleServerOptions { Bind = BindAddress.Parse("127.0.0.1:0"), MaxStreams = 2 });
        var url = new Uri($"ws://{server.BaseUrl.Authority}/api/stream?token={server.Token}");
        using var first = new ClientWebSocket();
        using var second = new ClientWebSocket();
        await first.ConnectAsync(url, CancellationToken.None);
        await second.ConnectAsync(url, CancellationToken.None);

        using var third = new ClientWebSocket();
        var refused = await Assert.ThrowsAnyAsync<WebSocketException>(() => third.ConnectAsync(url, CancellationToken.None));
        Assert.Contains("503", refused.Message, StringComparison.Ordinal);

        await first.CloseAsync(WebSocketCloseStatus.NormalClosure, null, CancellationToken.None);
        var waited = System.Diagnostics.Stopwatch.StartNew();
        ClientWebSocket again;
        while (true)
        {
            again = new ClientWebSocket();
            try
            {
                await again.ConnectAsync(url, CancellationToken.None); // the closed one's place is free again
                break;
            }
            catch (WebSocketException) when (waited.Elapsed < TimeSpan.FromSeconds(5))
            {
                again.Dispose();
                await Task.Delay(50); // the server frees the place when it has seen the close
            }
        }

        using var opened = again;
        Assert.Equal(WebSocketState.Open, opened.State);
    }
}
