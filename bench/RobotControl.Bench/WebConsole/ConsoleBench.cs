using System.Diagnostics;
using System.Globalization;
using System.Net.WebSockets;
using System.Text;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;
using RobotControl.WebConsole.Session;

namespace RobotControl.Bench.WebConsole;

/// <summary>
/// <c>console [--graph graphs/teleop-lb.json] [--seconds 15] [--clients 3] [--out docs/perf/console.md]</c>: the web
/// console on the virtual robot (real time): the loop's tick time and deadline misses of a session without clients
/// and of one streaming every joint position and command to N WebSocket clients at 60 Hz (each also polling status
/// and controllers as the pages do); frames and rows each client received; time to serve the page and its bundle.
/// </summary>
internal sealed class ConsoleBench : IBenchCommand
{
    public string Name => "console";

    public string Description => "Web console: tick p99 and misses with N streaming clients vs none; page and bundle serve time.";

    public int Run(string[] args)
    {
        var graph = Arg(args, "--graph") ?? "graphs/teleop-lb.json";
        var seconds = double.Parse(Arg(args, "--seconds") ?? "15", CultureInfo.InvariantCulture);
        var clients = int.Parse(Arg(args, "--clients") ?? "3", CultureInfo.InvariantCulture);
        var outPath = Arg(args, "--out") ?? "docs/perf/console.md";
        var c = CultureInfo.InvariantCulture;

        var (idle, _, _) = Measure(graph, seconds, 0).GetAwaiter().GetResult();
        var (busy, received, serve) = Measure(graph, seconds, clients).GetAwaiter().GetResult();

        var md = new StringBuilder();
        md.AppendLine("# Web console: loop timing with streaming clients");
        md.AppendLine();
        md.AppendLine(c, $"Command: `dotnet run -c Release --project bench/RobotControl.Bench -- console --graph {graph} --seconds {seconds} --clients {clients} --out {outPath}`");
        md.AppendLine();
        md.AppendLine(c, $"Measured {DateTime.UtcNow:yyyy-MM-dd HH:mm} UTC on {Environment.ProcessorCount} cores shared with other work. Two fresh sessions on the virtual robot (real firmware, paced to real time, 1 kHz loop), {seconds} s each: one without clients, one with {clients} WebSocket clients each subscribed to every joint's position and command ({received.Signals} signals) at 60 Hz and polling /api/status (1 Hz) and /api/controllers (3 Hz).");
        md.AppendLine();
        md.AppendLine("| run | ticks | median us | p99 us | max us | deadline misses |");
        md.AppendLine("|---|---|---|---|---|---|");
        md.AppendLine(c, $"| no clients | {idle.Ticks} | {idle.TickMedianUs:F1} | {idle.TickP99Us:F1} | {idle.TickMaxUs:F1} | {idle.DeadlineMisses} |");
        md.AppendLine(c, $"| {clients} clients at 60 Hz | {busy.Ticks} | {busy.TickMedianUs:F1} | {busy.TickP99Us:F1} | {busy.TickMaxUs:F1} | {busy.DeadlineMisses} |");
        md.AppendLine();
        md.AppendLine(c, $"p99 with clients / without: {busy.TickP99Us / Math.Max(idle.TickP99Us, 1e-9):F2} (target <= 1.10). Frames per client per second: {received.Frames / (double)Math.Max(1, clients) / seconds:F1}; rows per client per second: {received.Rows / (double)Math.Max(1, clients) / seconds:F0}.");
        md.AppendLine();
        md.AppendLine(c, $"Serving the page on localhost (index.html plus its script and style, HttpClient, warm): {serve.TotalMilliseconds:F1} ms.");
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(outPath))!);
        File.WriteAllText(outPath, md.ToString());
        System.Console.Write(md.ToString());
        return 0;
    }

    private static async Task<(SessionStatus Status, (int Signals, long Frames, long Rows) Received, TimeSpan Serve)> Measure(string graph, double seconds, int clients)
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);
        using var session = new HeadlessSession(new HeadlessSessionOptions { GraphPath = graph, Catalog = catalog, Virtual = true });
        await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
        var signals = session.Model.Arms.SelectMany(a => a.PositionSignals.Concat(a.CommandSignals)).ToList();
        using var stop = new CancellationTokenSource(TimeSpan.FromSeconds(seconds));
        long frames = 0, rows = 0;
        var tasks = Enumerable.Range(0, clients).Select(i => Task.Run(async () =>
        {
            using var http = new HttpClient { BaseAddress = server.BaseUrl };
            using var socket = new ClientWebSocket();
            await socket.ConnectAsync(new Uri($"ws://{server.BaseUrl.Authority}/api/stream"), CancellationToken.None);
            var subscribe = $"{{\"subscribe\":[{string.Join(',', signals.Select(s => $"\"{s}\""))}],\"rateHz\":60}}";
            await socket.SendAsync(Encoding.UTF8.GetBytes(subscribe), WebSocketMessageType.Text, true, CancellationToken.None);
            var poll = Task.Run(async () =>
            {
                for (var n = 0; !stop.IsCancellationRequested; n++)
                {
                    await http.GetStringAsync(n % 3 == 0 ? "api/status" : "api/controllers");
                    await Task.Delay(333);
                }
            });
            var buffer = new byte[1 << 20];
            try
            {
                while (!stop.IsCancellationRequested)
                {
                    var count = 0;
                    ValueWebSocketReceiveResult r;
                    do
                    {
                        r = await socket.ReceiveAsync(buffer.AsMemory(count), stop.Token);
                        count += r.Count;
                    }
                    while (!r.EndOfMessage);
                    var text = Encoding.UTF8.GetString(buffer, 0, count);
                    if (text.StartsWith("{\"t\":", StringComparison.Ordinal))
                    {
                        Interlocked.Increment(ref frames);
                        Interlocked.Add(ref rows, text.AsSpan(6, text.IndexOf(']', StringComparison.Ordinal) - 6).Count(',') + 1);
                    }
                }
            }
            catch (OperationCanceledException)
            {
                // Time is up.
            }

            await poll;
        })).ToList();
        if (clients == 0)
        {
            await Task.Delay(TimeSpan.FromSeconds(seconds));
        }

        await Task.WhenAll(tasks);
        var status = session.Status;
        using var page = new HttpClient { BaseAddress = server.BaseUrl };
        var html = await page.GetStringAsync("/");
        var watch = Stopwatch.StartNew();
        html = await page.GetStringAsync("/");
        foreach (var asset in System.Text.RegularExpressions.Regex.Matches(html, "(?:src|href)=\"(/assets/[^\"]+)\"").Select(m => m.Groups[1].Value))
        {
            await page.GetByteArrayAsync(asset);
        }

        return (status, (signals.Count, frames, rows), watch.Elapsed);
    }

    private static string? Arg(string[] args, string name)
    {
        var i = Array.IndexOf(args, name);
        return i >= 0 && i + 1 < args.Length ? args[i + 1] : null;
    }
}
