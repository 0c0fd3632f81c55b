using System.Net.WebSockets;
using System.Text;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.Bench.WebConsole;

/// <summary>
/// A console session with N WebSocket clients, each subscribed to every joint's position and command at 60 Hz and
/// polling <c>/api/status</c> and <c>/api/controllers</c> as the pages do; the loop's figures over the window.
/// </summary>
internal static class StreamingClients
{
    private static readonly TimeSpan WarmUp = TimeSpan.FromSeconds(1);

    /// <summary>Runs <paramref name="session"/> (disposed here) for <paramref name="seconds"/> with <paramref name="clients"/> clients.</summary>
    public static async Task<StreamRun> Measure(LiveSession session, double seconds, int clients)
    {
        using (session)
        {
            await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
            var signals = session.Model.Arms.SelectMany(a => a.PositionSignals.Concat(a.CommandSignals)).ToList();
            await Task.Delay(WarmUp);
            var start = session.Status;
            using var stop = new CancellationTokenSource(TimeSpan.FromSeconds(seconds));
            long frames = 0, rows = 0;
            var tasks = Enumerable.Range(0, clients).Select(_ => Task.Run(async () =>
            {
                var (f, r) = await Client(server, signals, stop.Token);
                Interlocked.Add(ref frames, f);
                Interlocked.Add(ref rows, r);
            })).ToList();
            if (clients == 0)
            {
                await Task.Delay(TimeSpan.FromSeconds(seconds));
            }

            await Task.WhenAll(tasks);
            var end = session.Status;
            var ticks = end.Ticks - start.Ticks;
            var allocated = (end.TickAllocatedBytes ?? 0) - (start.TickAllocatedBytes ?? 0);
            var perClient = Math.Max(1, clients) * seconds;
            return new StreamRun(
                clients,
                seconds,
                end.Ticks,
                end.TickMedianUs,
                end.TickP99Us,
                end.TickMaxUs,
                end.DeadlineMisses,
                ticks == 0 ? double.NaN : allocated / (double)ticks,
                frames / perClient,
                rows / perClient);
        }
    }

    private static async Task<(long Frames, long Rows)> Client(ConsoleServer server, List<string> signals, CancellationToken stop)
    {
        using var http = new HttpClient { BaseAddress = server.BaseUrl };
        http.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", server.Token);
        using var socket = new ClientWebSocket();
        await socket.ConnectAsync(new Uri($"ws://{server.BaseUrl.Authority}/api/stream?token={server.Token}"), CancellationToken.None);
        var subscribe = $"{{\"subscribe\":[{string.Join(',', signals.Select(s => $"\"{s}\""))}],\"rateHz\":60}}";
        await socket.SendAsync(Encoding.UTF8.GetBytes(subscribe), WebSocketMessageType.Text, true, CancellationToken.None);
        var poll = Task.Run(async () =>
        {
            for (var n = 0; !stop.IsCancellationRequested; n++)
            {
                await http.GetStringAsync(n % 3 == 0 ? "api/status" : "api/controllers");
                await Task.Delay(333, CancellationToken.None);
            }
        }, CancellationToken.None);
        long frames = 0, rows = 0;
        var buffer = new byte[1 << 20];
        try
        {
            while (!stop.IsCancellationRequested)
            {
                var count = 0;
                ValueWebSocketReceiveResult r;
                do
                {
                    r = await socket.ReceiveAsync(buffer.AsMemory(count), stop);
                    count += r.Count;
                }
                while (!r.EndOfMessage);
                var text = Encoding.UTF8.GetString(buffer, 0, count);
                if (text.StartsWith("{\"t\":", StringComparison.Ordinal))
                {
                    frames++;
                    rows += text.AsSpan(6, text.IndexOf(']', StringComparison.Ordinal) - 6).Count(',') + 1;
                }
            }
        }
        catch (OperationCanceledException)
        {
            // Time is up.
        }

        await poll;
        return (frames, rows);
    }
}
