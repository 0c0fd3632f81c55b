using System.Globalization;
using System.Text.Json;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.Bench.WebConsole;

/// <summary>
/// <c>console [--graph graphs/teleop-lb.json] [--seconds 10] [--clients 3] [--repeats 3] [--chromium /usr/bin/chromium]
/// [--dist &lt;assets folder of the front-end build&gt;] [--out docs/perf/console.json]</c>: the web console on the virtual robot (real time). Per repeat, two fresh sessions:
/// one without clients and one streaming every joint position and command to N WebSocket clients at 60 Hz (each also
/// polling status and controllers as the pages do): the loop's tick time, deadline misses and bytes allocated per
/// tick. Then, in headless Chromium: the signal-change-to-display latency (a timestamp round trip in the page), the
/// first page load (cold cache) and the JavaScript bundle size. Writes JSON.
/// </summary>
internal sealed class ConsoleBench : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.CamelCase };

    public string Name => "console";

    public string Description => "Web console: tick p99, misses and B/tick with N streaming clients vs none; display latency, first load, bundle size.";

    public int Run(string[] args)
    {
        var c = CultureInfo.InvariantCulture;
        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var seconds = double.Parse(BenchArgs.Value(args, "--seconds") ?? "10", c);
        var clients = int.Parse(BenchArgs.Value(args, "--clients") ?? "3", c);
        var repeats = int.Parse(BenchArgs.Value(args, "--repeats") ?? "3", c);
        var chromium = BenchArgs.Value(args, "--chromium") ?? "/usr/bin/chromium";
        var outPath = BenchArgs.Value(args, "--out") ?? "docs/perf/console.json";
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);

        var runs = new List<StreamRun>();
        for (var r = 0; r < repeats; r++)
        {
            runs.Add(StreamingClients.Measure(Open(graph, catalog), seconds, 0).GetAwaiter().GetResult());
            runs.Add(StreamingClients.Measure(Open(graph, catalog), seconds, clients).GetAwaiter().GetResult());
            System.Console.WriteLine(string.Create(c, $"repeat {r + 1}: p99 {runs[^2].TickP99Us:F1} us without clients, {runs[^1].TickP99Us:F1} us with {clients}"));
        }

        var browser = BrowserMeasures.Measure(Open(graph, catalog), chromium).GetAwaiter().GetResult();
        var chunks = BrowserMeasures.AllChunks(BenchArgs.Value(args, "--dist") ?? "src/RobotControl.Console/web/dist/assets");
        var idle = runs.Where(x => x.Clients == 0).ToList();
        var busy = runs.Where(x => x.Clients > 0).ToList();
        var summary = new
        {
            tickP99UsNoClients = Median(idle.Select(x => x.TickP99Us)),
            tickP99UsWithClients = Median(busy.Select(x => x.TickP99Us)),
            p99Ratio = Median(busy.Select(x => x.TickP99Us)) / Median(idle.Select(x => x.TickP99Us)),
            deadlineMissesWithClients = busy.Sum(x => x.DeadlineMisses),
            allocatedBytesPerTickWithClients = Median(busy.Select(x => x.AllocatedBytesPerTick)),
            framesPerClientPerSecond = Median(busy.Select(x => x.FramesPerClientPerSecond)),
            browser.DisplayLatencyMedianMs,
            browser.AfterReplyLatencyMedianMs,
            browser.FirstLoadMedianMs,
            browser.LoadEventMedianMs,
            browser.FirstLoadJsBytes,
            browser.FirstLoadJsGzipBytes,
            allJsBytes = chunks.Js,
            allJsGzipBytes = chunks.Gzip,
        };
        var command = $"dotnet run -c Release --project bench/RobotControl.Bench -- console --graph {graph} --seconds {seconds.ToString(c)} --clients {clients} --repeats {repeats} --out {outPath}";
        var json = JsonSerializer.Serialize(new { command, measuredUtc = DateTime.UtcNow, Environment.ProcessorCount, graph, seconds, clients, repeats, summary, runs, browser }, JsonOptions);
        Directory.CreateDirectory(Path.GetDirectoryName(Path.GetFullPath(outPath))!);
        File.WriteAllText(outPath, json);
        System.Console.WriteLine(JsonSerializer.Serialize(summary, JsonOptions));
        return 0;
    }

    internal static double Median(IEnumerable<double> values)
    {
        var sorted = values.Order().ToArray();
        return sorted.Length == 0 ? double.NaN : sorted.Length % 2 == 1 ? sorted[sorted.Length / 2] : (sorted[(sorted.Length / 2) - 1] + sorted[sorted.Length / 2]) / 2;
    }

    private static LiveSession Open(string graph, PluginCatalog catalog) =>
        new(new LiveSessionOptions { GraphPath = graph, Catalog = catalog, Virtual = true });

}

/// <summary>One session's loop figures over the measured window.</summary>
internal sealed record StreamRun(int Clients, double Seconds, long Ticks, double TickMedianUs, double TickP99Us, double TickMaxUs, long DeadlineMisses, double AllocatedBytesPerTick, double FramesPerClientPerSecond, double RowsPerClientPerSecond);
