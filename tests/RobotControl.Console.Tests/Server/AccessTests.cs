using System.Net;
using System.Net.Http.Headers;
using System.Net.WebSockets;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Server;

[Collection(ConsoleCollection.Name)]
public sealed class AccessTests(ConsoleFixture console)
{
    [Fact]
    public async Task A_non_loopback_bind_without_a_token_gets_one_and_its_api_refuses_requests_without_it()
    {
        await using var server = await ConsoleServer.StartAsync(console.Session, BindAddress.Parse("0.0.0.0:0"), null);
        Assert.Equal(32, server.Token.Length);
        Assert.Equal($"?token={server.Token}", server.OpenUrl.Query);
        var local = new Uri($"http://127.0.0.1:{server.BaseUrl.Port}/");
        using var http = new HttpClient { BaseAddress = local };
        Assert.Equal(HttpStatusCode.Unauthorized, (await http.GetAsync("api/status")).StatusCode);
        using var wrong = new HttpRequestMessage(HttpMethod.Get, "api/status");
        wrong.Headers.Authorization = new AuthenticationHeaderValue("Bearer", "not-the-token");
        Assert.Equal(HttpStatusCode.Unauthorized, (await http.SendAsync(wrong)).StatusCode);
        using var right = new HttpRequestMessage(HttpMethod.Get, "api/status");
        right.Headers.Authorization = new AuthenticationHeaderValue("Bearer", server.Token);
        Assert.Equal(HttpStatusCode.OK, (await http.SendAsync(right)).StatusCode);
        Assert.Equal(HttpStatusCode.OK, (await http.GetAsync($"api/status?token={server.Token}")).StatusCode);

        using var socket = new ClientWebSocket();
        await Assert.ThrowsAnyAsync<WebSocketException>(() => socket.ConnectAsync(new Uri($"ws://127.0.0.1:{server.BaseUrl.Port}/api/stream"), CancellationToken.None));
        using var withToken = new ClientWebSocket();
        await withToken.ConnectAsync(new Uri($"ws://127.0.0.1:{server.BaseUrl.Port}/api/stream?token={server.Token}"), CancellationToken.None);
        Assert.Equal(WebSocketState.Open, withToken.State);
    }

    [Fact]
    public async Task A_loopback_console_needs_its_token_too_and_serves_its_pages_without_it()
    {
        using var anonymous = new HttpClient { BaseAddress = console.Server.BaseUrl };
        anonymous.DefaultRequestHeaders.Add(OperatorRole.ClientHeader, "local-account");
        Assert.Equal(HttpStatusCode.Unauthorized, (await anonymous.GetAsync("api/status")).StatusCode);
        Assert.Equal(HttpStatusCode.Unauthorized, (await anonymous.PostAsync("api/operator", null)).StatusCode);
        Assert.Null(console.Server.Operator.Holder);
        var page = await anonymous.GetAsync("/");
        Assert.Equal(HttpStatusCode.OK, page.StatusCode); // the page holds no session data; it reads the token from the URL
        Assert.Contains("<main id=\"page\">", await page.Content.ReadAsStringAsync(), StringComparison.Ordinal);
    }

    [Fact]
    public async Task A_websocket_from_another_origin_is_refused_and_one_from_the_console_streams()
    {
        var ws = new Uri($"ws://{console.Server.BaseUrl.Authority}/api/stream?token={console.Server.Token}");
        using var foreign = new ClientWebSocket();
        foreign.Options.SetRequestHeader("Origin", "http://evil.example");
        await Assert.ThrowsAnyAsync<WebSocketException>(() => foreign.ConnectAsync(ws, CancellationToken.None));

        using var own = new ClientWebSocket();
        own.Options.SetRequestHeader("Origin", $"http://{console.Server.BaseUrl.Authority}");
        await own.ConnectAsync(ws, CancellationToken.None);
        await own.SendAsync("{\"subscribe\":[\"robot.right.elbow.position\"],\"rateHz\":60,\"id\":1}"u8.ToArray(), WebSocketMessageType.Text, true, CancellationToken.None);
        await own.SendAsync("{\"subscribe\":[\"robot.right.elbow.command\",\"robot.left.elbow.position\"],\"rateHz\":60,\"id\":2}"u8.ToArray(), WebSocketMessageType.Text, true, CancellationToken.None);
        var buffer = new byte[1 << 16];
        var frames = new List<System.Text.Json.JsonElement>();
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(10));
        while (frames.Count < 5)
        {
            var r = await own.ReceiveAsync(buffer, timeout.Token);
            var message = System.Text.Json.JsonDocument.Parse(buffer.AsMemory(0, r.Count)).RootElement.Clone();
            if (message.TryGetProperty("t", out _))
            {
                frames.Add(message);
            }
        }

        // Every frame names the subscription it was cut for: the last ones carry both columns of subscription 2.
        var last = frames[^1];
        Assert.Equal(2, last.GetProperty("id").GetInt64());
        Assert.Equal(2, last.GetProperty("v").GetArrayLength());
        Assert.All(frames, f => Assert.Equal(f.GetProperty("id").GetInt64() == 2 ? 2 : 1, f.GetProperty("v").GetArrayLength()));
    }

    [Fact]
    public async Task A_cross_origin_action_is_refused()
    {
        using var http = await console.Operator("operator-origin");
        using var request = new HttpRequestMessage(HttpMethod.Post, "api/torque") { Content = new StringContent("{\"on\":true}") };
        request.Headers.Add("Origin", "http://evil.example");
        Assert.Equal(HttpStatusCode.Forbidden, (await http.SendAsync(request)).StatusCode);
        console.ReleaseOperator();
    }
}
