using System.Diagnostics;
using System.IO.Compression;
using System.Net.Http.Json;
using System.Text.RegularExpressions;
using Microsoft.Playwright;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.Bench.WebConsole;

/// <summary>What headless Chromium measures against a console on the virtual robot.</summary>
/// <param name="DisplayLatencyMs">Per trial: the page sends a setpoint, and times (on its own clock) until the joint's streamed position has moved and the next animation frame is drawn.</param>
/// <param name="AfterReplyLatencyMs">Per trial: the same, from the setpoint's HTTP reply (the command applied) to the drawn frame.</param>
/// <param name="FirstLoadMs">Per load, cold cache: navigation start until the bus page lists every module.</param>
/// <param name="LoadEventMs">Per load: the navigation's load event end.</param>
internal sealed record BrowserResult(
    IReadOnlyList<double> DisplayLatencyMs,
    IReadOnlyList<double> AfterReplyLatencyMs,
    IReadOnlyList<double> FirstLoadMs,
    IReadOnlyList<double> LoadEventMs,
    long FirstLoadJsBytes,
    long FirstLoadJsGzipBytes)
{
    public double DisplayLatencyMedianMs => ConsoleBench.Median(DisplayLatencyMs);

    public double AfterReplyLatencyMedianMs => ConsoleBench.Median(AfterReplyLatencyMs);

    public double FirstLoadMedianMs => ConsoleBench.Median(FirstLoadMs);

    public double LoadEventMedianMs => ConsoleBench.Median(LoadEventMs);
}

/// <summary>Display latency, first page load and bundle size, in Debian's Chromium driven by Playwright.</summary>
internal static class BrowserMeasures
{
    private const string Client = "bench-latency";
    private const string Motor = "right.elbow";
    private const int Trials = 30;
    private const int Loads = 5;

    // In the page: subscribe to the joint's position at 60 Hz; per trial note the time, send a setpoint 10 degrees
    // away, wait until a streamed value has moved 0.1 degree, wait for the next animation frame, note the time.
    private const string LatencyScript = """
        async ({ signal, motor, trials, client }) => {
          const post = (path, body) => fetch('/api' + path, { method: 'POST', headers: { 'Content-Type': 'application/json', 'X-Console-Client': client, Authorization: 'Bearer ' + sessionStorage.getItem('rc-console-token') }, body: JSON.stringify(body) });
          const ws = new WebSocket(`ws://${location.host}/api/stream?token=${sessionStorage.getItem('rc-console-token')}`);
          let latest = NaN, waiter = null;
          ws.onmessage = (e) => {
            const m = JSON.parse(e.data);
            if (m.v && m.v[0] && m.v[0].length) { latest = m.v[0][m.v[0].length - 1]; if (waiter) waiter(); }
          };
          await new Promise((r) => { ws.onopen = r; });
          ws.send(JSON.stringify({ subscribe: [signal], rateHz: 60 }));
          const until = (test) => new Promise((r) => { waiter = () => { if (test()) { waiter = null; r(); } }; waiter(); });
          await until(() => !Number.isNaN(latest));
          const total = [], afterReply = [];
          for (let i = 0; i < trials; i++) {
            await new Promise((r) => setTimeout(r, 400));
            const from = latest;
            const deg = i % 2 === 0 ? 55 : 45;
            const t0 = performance.now();
            let tReply = NaN;
            const moved = until(() => Math.abs(latest - from) > 0.1 * Math.PI / 180);
            const reply = await post(`/motors/${motor}/setpoint`, { deg });
            tReply = performance.now();
            if (!reply.ok) throw new Error(await reply.text());
            await moved;
            await new Promise((r) => requestAnimationFrame(() => r()));
            const t1 = performance.now();
            total.push(t1 - t0); afterReply.push(t1 - tReply);
          }
          ws.close();
          return [...total, ...afterReply];
        }
        """;

    /// <summary>Measures against <paramref name="session"/> (disposed here) with the browser at <paramref name="chromium"/>.</summary>
    public static async Task<BrowserResult> Measure(LiveSession session, string chromium)
    {
        using (session)
        {
            await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
            using var playwright = await Playwright.CreateAsync();
            await using var browser = await playwright.Chromium.LaunchAsync(new BrowserTypeLaunchOptions
            {
                ExecutablePath = chromium,
                Headless = true,
                Args = ["--no-sandbox", "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run"],
            });
            var (first, loadEvent) = await FirstLoads(browser, server.OpenUrl);
            var right = session.Model.Arms.First(a => a.Name == "right");
            var signal = right.PositionSignals[right.Joints.ToList().IndexOf("right_elbow")];
            var (total, afterReply) = await Latency(browser, server.OpenUrl, server.Token, signal);
            var (js, gzip) = await Bundle(server.BaseUrl);
            return new BrowserResult(total, afterReply, first, loadEvent, js, gzip);
        }
    }

    private static async Task<(List<double> First, List<double> LoadEvent)> FirstLoads(IBrowser browser, Uri url)
    {
        var first = new List<double>();
        var loadEvent = new List<double>();
        for (var i = 0; i < Loads; i++)
        {
            await using var context = await browser.NewContextAsync(new() { ViewportSize = new() { Width = 1400, Height = 900 } });
            var page = await context.NewPageAsync();
            var watch = Stopwatch.StartNew();
            await page.GotoAsync(new Uri(url, "#bus").ToString());
            await page.WaitForFunctionAsync("() => document.querySelectorAll('[data-controller]').length >= 6 && document.querySelector('[data-field=position]')?.textContent !== ''");
            first.Add(watch.Elapsed.TotalMilliseconds);
            loadEvent.Add(await page.EvaluateAsync<double>("() => performance.getEntriesByType('navigation')[0].loadEventEnd"));
        }

        return (first, loadEvent);
    }

    private static async Task<(List<double> Total, List<double> AfterReply)> Latency(IBrowser browser, Uri url, string token, string signal)
    {
        using var http = new HttpClient { BaseAddress = url };
        http.DefaultRequestHeaders.Add(OperatorRole.ClientHeader, Client);
        http.DefaultRequestHeaders.Authorization = new System.Net.Http.Headers.AuthenticationHeaderValue("Bearer", token);
        (await http.PostAsync("api/operator", null)).EnsureSuccessStatusCode();
        (await http.PostAsJsonAsync("api/pedal", new { down = true })).EnsureSuccessStatusCode();
        try
        {
            await using var context = await browser.NewContextAsync();
            var page = await context.NewPageAsync();
            await page.GotoAsync(new Uri(url, "#status").ToString());
            var all = await page.EvaluateAsync<double[]>(LatencyScript, new { signal, motor = Motor, trials = Trials, client = Client });
            return ([.. all.Take(Trials)], [.. all.Skip(Trials)]);
        }
        finally
        {
            (await http.PostAsync($"api/motors/{Motor}/release", null)).EnsureSuccessStatusCode();
            (await http.PostAsJsonAsync("api/pedal", new { down = false })).EnsureSuccessStatusCode();
        }
    }

    /// <summary>The JavaScript the first load fetches (script and module preloads of index.html), raw and gzip.</summary>
    private static async Task<(long Js, long Gzip)> Bundle(Uri url)
    {
        using var http = new HttpClient { BaseAddress = url };
        var html = await http.GetStringAsync("/");
        long js = 0, gzip = 0;
        foreach (var asset in Regex.Matches(html, "(?:src|href)=\"(/assets/[^\"]+\\.js)\"").Select(m => m.Groups[1].Value).Distinct())
        {
            var bytes = await http.GetByteArrayAsync(asset);
            js += bytes.Length;
            gzip += Gzipped(bytes);
        }

        return (js, gzip);
    }

    /// <summary>Every JavaScript chunk the build wrote (web/dist/assets), raw and gzip.</summary>
    public static (long Js, long Gzip) AllChunks(string distAssets)
    {
        long js = 0, gzip = 0;
        foreach (var file in Directory.GetFiles(distAssets, "*.js"))
        {
            var bytes = File.ReadAllBytes(file);
            js += bytes.Length;
            gzip += Gzipped(bytes);
        }

        return (js, gzip);
    }

    private static long Gzipped(byte[] bytes)
    {
        using var packed = new MemoryStream();
        using (var zip = new GZipStream(packed, CompressionLevel.SmallestSize, leaveOpen: true))
        {
            zip.Write(bytes);
        }

        return packed.Length;
    }
}
