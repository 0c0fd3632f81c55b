using System.Diagnostics;
using System.Net.Http.Json;
using System.Text.Json;
using Microsoft.AspNetCore.Http;
using RobotControl.Cli;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.Bench.EStop;

/// <summary>
/// One console on the virtual robot, served on 127.0.0.1:0, and the stops made through it: each
/// <c>POST /api/estop</c> from a watching console (no operator role), its arrival timestamped by the server's outermost
/// middleware, its first stop frame by the tapped bus link; after each, the operator's reset
/// (<c>POST /api/faults/clear</c>, <c>POST /api/torque {"on":true}</c>) back to PEDAL_UP.
/// </summary>
internal sealed class EStopRun : IAsyncDisposable
{
    private const string EStopPath = "/api/estop";
    private static readonly TimeSpan FrameWait = TimeSpan.FromSeconds(10);
    private static readonly TimeSpan ReadyWait = TimeSpan.FromSeconds(60);
    private readonly LiveSession _session;
    private readonly EStopTapLink _tap;
    private readonly ConsoleServer _server;
    private readonly HttpClient _watcher;
    private readonly HttpClient _operator;

    private EStopRun(LiveSession session, EStopTapLink tap, ConsoleServer server)
    {
        _session = session;
        _tap = tap;
        _server = server;
        _watcher = Client("bench-watcher");
        _operator = Client("bench-operator");
    }

    /// <summary>The server's base URL.</summary>
    public Uri BaseUrl => _server.BaseUrl;

    /// <summary>The console's access token.</summary>
    public string Token => _server.Token;

    /// <summary>Brings the console up on <paramref name="graph"/>; stops end at a frame of kind <paramref name="wanted"/>.</summary>
    public static async Task<EStopRun> Start(string graph, StopFrame wanted)
    {
        EStopTapLink? tap = null;
        var session = new LiveSession(new LiveSessionOptions
        {
            GraphPath = graph,
            Catalog = ShippedPlugins.Catalog(),
            Virtual = true,
            WrapLink = (link, clock) => tap = new EStopTapLink(link, clock),
        });
        try
        {
            var t = tap ?? throw new InvalidOperationException("the session did not open its bus through the benchmark's link");
            t.Wanted = wanted;
            var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null, first: (http, next) =>
            {
                if (HttpMethods.IsPost(http.Request.Method) && http.Request.Path == EStopPath)
                {
                    t.Arm(Stopwatch.GetTimestamp());
                }

                return next(http);
            }).ConfigureAwait(false);
            return new EStopRun(session, t, server);
        }
        catch
        {
            session.Dispose();
            throw;
        }
    }

    /// <summary>
    /// One stop: waits for PEDAL_UP or PEDAL_DOWN and then <paramref name="settle"/>, runs <paramref name="beforeStop"/>
    /// (e.g. queues work), sends the E-STOP and measures from its arrival at the server to its first stop frame on the
    /// wire (whatever the console answers: a 503 says the run level had not reached E_STOP within its 1 s); then
    /// awaits <paramref name="beforeStop"/>'s work and resets to PEDAL_UP.
    /// </summary>
    /// <exception cref="InvalidOperationException">No stop frame came, or the robot did not come back.</exception>
    public async Task<StopSample> Stop(TimeSpan settle, Func<Task<Task>>? beforeStop)
    {
        await WaitForLevel(["PEDAL_UP", "PEDAL_DOWN"]).ConfigureAwait(false);
        await Task.Delay(settle).ConfigureAwait(false);
        var queued = beforeStop is null ? Task.CompletedTask : await beforeStop().ConfigureAwait(false);
        bool confirmed;
        using (var response = await _watcher.PostAsync(EStopPath.TrimStart('/'), null).ConfigureAwait(false))
        {
            confirmed = response.IsSuccessStatusCode;
        }

        var waited = Stopwatch.StartNew();
        long frame;
        while (!_tap.TryTake(out frame, out _))
        {
            if (waited.Elapsed > FrameWait)
            {
                throw new InvalidOperationException($"no {_tap.Wanted} frame on the wire within {FrameWait.TotalSeconds:0} s of the E-STOP's answer ({(confirmed ? "E_STOP confirmed" : "E_STOP not confirmed")})");
            }

            await Task.Delay(1).ConfigureAwait(false);
        }

        var arrival = _tap.ArrivedAt;
        var lastCycle = _tap.CycleStartsSince(arrival - (FrameWait.Ticks * Stopwatch.Frequency / TimeSpan.TicksPerSecond)).Where(t => t < arrival).DefaultIfEmpty(arrival).Max();
        await queued.WaitAsync(ReadyWait).ConfigureAwait(false);
        await Reset().ConfigureAwait(false);
        return new StopSample(Ms(frame - arrival), Ms(arrival - lastCycle), confirmed);
    }

    /// <summary>Bus cycle periods (goal SYNC WRITE to goal SYNC WRITE), milliseconds, from <paramref name="since"/> (a <see cref="Stopwatch"/> timestamp).</summary>
    public double[] CyclePeriodsMs(long since)
    {
        var starts = _tap.CycleStartsSince(since);
        return [.. starts.Skip(1).Select((t, i) => Ms(t - starts[i]))];
    }

    private static double Ms(long stopwatchTicks) => stopwatchTicks * 1000.0 / Stopwatch.Frequency;

    /// <summary>Queues <paramref name="count"/> parameter reloads of the modules (round robin) on the session, as the console's reload button does.</summary>
    public Task[] QueueReloads(int count)
    {
        var ids = _session.Controllers.Where(c => c.Present).Select(c => c.Id).ToArray();
        return ids.Length == 0 ? [] : [.. Enumerable.Range(0, count).Select(i => _session.ReloadParametersAsync(ids[i % ids.Length]))];
    }

    private async Task Reset()
    {
        await Operator("api/operator", null).ConfigureAwait(false);
        await Operator("api/faults/clear", null).ConfigureAwait(false);
        await Operator("api/torque", new { on = true }).ConfigureAwait(false);
        await WaitForLevel(["PEDAL_UP", "PEDAL_DOWN"]).ConfigureAwait(false);
    }

    private async Task Operator(string path, object? body)
    {
        using var response = body is null ? await _operator.PostAsync(path, null).ConfigureAwait(false) : await _operator.PostAsJsonAsync(path, body).ConfigureAwait(false);
        if (!response.IsSuccessStatusCode)
        {
            throw new InvalidOperationException($"POST /{path}: {(int)response.StatusCode} {await response.Content.ReadAsStringAsync().ConfigureAwait(false)}");
        }
    }

    private async Task WaitForLevel(string[] levels)
    {
        var waited = Stopwatch.StartNew();
        var level = "?";
        while (waited.Elapsed < ReadyWait)
        {
            using var doc = JsonDocument.Parse(await _operator.GetStringAsync("api/status").ConfigureAwait(false));
            level = doc.RootElement.GetProperty("status").GetProperty("robotState").GetString() ?? "?";
            if (levels.Contains(level))
            {
                return;
            }

            await Task.Delay(20).ConfigureAwait(false);
        }

        throw new InvalidOperationException($"the run level stayed {level} for {ReadyWait.TotalSeconds:0} s (waiting for {string.Join(" or ", levels)})");
    }

    private HttpClient Client(string name)
    {
        var client = new HttpClient { BaseAddress = _server.BaseUrl };
        client.DefaultRequestHeaders.Add(OperatorRole.ClientHeader, name);
        client.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", _server.Token);
        return client;
    }

    public async ValueTask DisposeAsync()
    {
        _watcher.Dispose();
        _operator.Dispose();
        await _server.DisposeAsync().ConfigureAwait(false);
        _session.Dispose();
    }
}

/// <summary>
/// One stop: milliseconds from the request's arrival to the first stop frame; how long the bus had written no goals
/// when the request arrived (a bus that had stopped cycling: the session sleeping or not scheduled); whether the
/// console confirmed E_STOP (within its 1 s).
/// </summary>
internal readonly record struct StopSample(double LatencyMs, double BusSilentAtArrivalMs, bool Confirmed);
