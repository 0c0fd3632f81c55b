using System.Net.WebSockets;
using System.Text.Json;
using Microsoft.AspNetCore.Builder;
using Microsoft.AspNetCore.Http;
using Microsoft.AspNetCore.Routing;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Server;

/// <summary>
/// <c>/api/stream</c>: a WebSocket per page. The page sends <c>{"subscribe": [signal, ...], "rateHz": 60}</c>; the
/// server then samples the signal ring at that rate (at most 60 Hz) and sends the rows recorded since the last frame
/// as <c>{"t": [...], "v": [[...], ...], "seq": n, "serverMs": ...}</c> (values in subscription order); its answer to a
/// subscription names the server's run (<c>"instance"</c>, <see cref="ConsoleServer.Instance"/>), ahead of the frames. The page may
/// send <c>{"ping": x}</c> and gets <c>{"pong": x, "serverMs": ...}</c> (latency measurement). Reading the ring takes no
/// lock and never touches the loop. Each client's frames are serialized once, into a <see cref="FrameQueue"/> that
/// drops the oldest when the client falls behind (a frame's <c>dropped</c> counts them); at most
/// <c>maxStreams</c> clients stream at once (503 for more).
/// </summary>
internal static class StreamEndpoint
{
    private const double MaxRateHz = 60;
    private const int MaxRowsPerFrame = 200;

    public static void Map(IEndpointRouteBuilder app, IConsoleSession session, int maxStreams, int queueFrames, string instance)
    {
        var streaming = 0;
        app.Map("/api/stream", async (HttpContext http) =>
        {
            if (!http.WebSockets.IsWebSocketRequest)
            {
                http.Response.StatusCode = StatusCodes.Status400BadRequest;
                await http.Response.WriteAsJsonAsync(new ApiError("stream: open it as a WebSocket")).ConfigureAwait(false);
                return;
            }

            if (Interlocked.Increment(ref streaming) > maxStreams)
            {
                Interlocked.Decrement(ref streaming);
                http.Response.StatusCode = StatusCodes.Status503ServiceUnavailable;
                await http.Response.WriteAsJsonAsync(new ApiError($"stream: {maxStreams} clients stream already (the most this console serves); close one"), ConsoleJson.Options).ConfigureAwait(false);
                return;
            }

            try
            {
                using var socket = await http.WebSockets.AcceptWebSocketAsync().ConfigureAwait(false);
                using var client = new Client(socket, session.Signals, new FrameQueue(queueFrames), instance);
                await client.Run(http.RequestAborted).ConfigureAwait(false);
            }
            finally
            {
                Interlocked.Decrement(ref streaming);
            }
        });
    }

    private sealed class Client(WebSocket socket, SignalRing ring, FrameQueue queue, string instance) : IDisposable
    {
        private readonly SemaphoreSlim _send = new(1, 1);
        private volatile Subscription _subscription = new([], [], 1 / MaxRateHz, 0);
        private long _cursor = ring.Written;

        public async Task Run(CancellationToken aborted)
        {
            using var stop = CancellationTokenSource.CreateLinkedTokenSource(aborted);
            var cutter = CutLoop(stop.Token);
            var sender = SendLoop(stop.Token);
            try
            {
                await ReceiveLoop(stop.Token).ConfigureAwait(false);
            }
            finally
            {
                await stop.CancelAsync().ConfigureAwait(false);
                try
                {
                    await Task.WhenAll(cutter, sender).ConfigureAwait(false);
                }
                catch (OperationCanceledException)
                {
                    // Closing.
                }
            }
        }

        public void Dispose() => _send.Dispose();

        private async Task ReceiveLoop(CancellationToken token)
        {
            var buffer = new byte[16 * 1024];
            while (socket.State == WebSocketState.Open && !token.IsCancellationRequested)
            {
                var count = 0;
                ValueWebSocketReceiveResult result;
                do
                {
                    result = await socket.ReceiveAsync(buffer.AsMemory(count), token).ConfigureAwait(false);
                    count += result.Count;
                }
                while (!result.EndOfMessage && count < buffer.Length);

                if (result.MessageType == WebSocketMessageType.Close)
                {
                    await socket.CloseOutputAsync(WebSocketCloseStatus.NormalClosure, null, CancellationToken.None).ConfigureAwait(false);
                    return;
                }

                await Handle(buffer.AsMemory(0, count), token).ConfigureAwait(false);
            }
        }

        private async Task Handle(ReadOnlyMemory<byte> message, CancellationToken token)
        {
            try
            {
                using var doc = JsonDocument.Parse(message);
                var root = doc.RootElement;
                if (root.TryGetProperty("ping", out var ping))
                {
                    await Send(new { Pong = ping.Clone(), ServerMs = DateTimeOffset.UtcNow.ToUnixTimeMilliseconds() }, token).ConfigureAwait(false);
                }

                if (root.TryGetProperty("subscribe", out var names))
                {
                    var wanted = names.EnumerateArray().Select(n => n.GetString() ?? string.Empty).ToList();
                    var unknown = wanted.Where(n => ring.IndexOf(n) < 0).ToList();
                    var rate = root.TryGetProperty("rateHz", out var r) && r.TryGetDouble(out var hz) && hz > 0 ? Math.Min(hz, MaxRateHz) : MaxRateHz;
                    var known = wanted.Where(n => ring.IndexOf(n) >= 0).ToList();
                    Interlocked.Exchange(ref _cursor, Math.Max(0, ring.Written - 1)); // the latest row first: a still session (a paused replay) shows its state at once
                    var id = root.TryGetProperty("id", out var given) && given.TryGetInt64(out var n) ? n : 0;
                    _subscription = new Subscription(known, [.. known.Select(ring.IndexOf)], 1 / rate, id);
                    await Send(new { Subscribed = known, Unknown = unknown, RateHz = rate, Id = id, Instance = instance }, token).ConfigureAwait(false);
                }
            }
            catch (Exception ex) when (ex is JsonException or InvalidOperationException or KeyNotFoundException)
            {
                await Send(new { Error = $"stream: malformed message ({ex.Message.Split(". ")[0]}); send {{\"subscribe\": [names], \"rateHz\": 60}}" }, token).ConfigureAwait(false);
            }
        }

        /// <summary>Cuts a frame of the rows since the last one each period, into the queue (never waits for the client).</summary>
        private async Task CutLoop(CancellationToken token)
        {
            while (!token.IsCancellationRequested && socket.State == WebSocketState.Open)
            {
                await Task.Delay(TimeSpan.FromSeconds(_subscription.PeriodS), token).ConfigureAwait(false);
                var subscription = _subscription;
                if (subscription.Columns.Count == 0)
                {
                    continue;
                }

                var slice = ring.Read(Interlocked.Read(ref _cursor), subscription.Columns, MaxRowsPerFrame);
                Interlocked.Exchange(ref _cursor, slice.Next);
                if (slice.Times.Count > 0)
                {
                    queue.Add(JsonSerializer.SerializeToUtf8Bytes(new { T = slice.Times, V = slice.Values, Seq = slice.Next, Id = subscription.Id, Dropped = queue.Dropped, ServerMs = DateTimeOffset.UtcNow.ToUnixTimeMilliseconds() }, ConsoleJson.Options));
                }
            }
        }

        /// <summary>Sends the queued frames as fast as the client takes them.</summary>
        private async Task SendLoop(CancellationToken token)
        {
            while (!token.IsCancellationRequested && socket.State == WebSocketState.Open)
            {
                var frame = await queue.NextAsync(token).ConfigureAwait(false);
                await SendBytes(frame, token).ConfigureAwait(false);
            }
        }

        private Task Send(object message, CancellationToken token) => SendBytes(JsonSerializer.SerializeToUtf8Bytes(message, ConsoleJson.Options), token);

        private async Task SendBytes(byte[] bytes, CancellationToken token)
        {
            await _send.WaitAsync(token).ConfigureAwait(false);
            try
            {
                await socket.SendAsync(bytes, WebSocketMessageType.Text, true, token).ConfigureAwait(false);
            }
            finally
            {
                _send.Release();
            }
        }
    }

    /// <summary>What a client streams; <paramref name="Id"/> is the client's number for it, echoed in every frame.</summary>
    private sealed record Subscription(IReadOnlyList<string> Names, IReadOnlyList<int> Columns, double PeriodS, long Id);
}
