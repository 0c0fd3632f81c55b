using System.Diagnostics;
using System.Globalization;
using System.Text.RegularExpressions;
using Microsoft.AspNetCore.Http;
using Microsoft.Playwright;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>
/// The console server restarted on the same address while its pages stay open (docs/console.md, "After a restart"): the
/// pages notice the new run without a reload and start again: no sample of the old run in the plot, the event log the
/// new session's only, no stale error banner, the operator role taken again (or the banner saying who took it first).
/// </summary>
[Collection(ConsoleCollection.Name)]
public sealed class RestartTests(ConsoleFixture console)
{
    private static readonly string[] Pages = ["plots", "status", "bus", "surgeon"];

    [Fact]
    public async Task After_a_restart_every_page_starts_again_and_the_operator_takes_the_role_again()
    {
        await using var restart = await Restart.Open(console, Pages);
        var plots = restart.Tab("plots");
        await Expect(plots, "#role[data-role=operator]", "operator");

        var aheadOf = await restart.StopTheFirstRun();
        foreach (var (name, tab) in restart.Tabs)
        {
            // While the server cannot be reached, nothing under the banner looks live.
            Assert.True(await tab.GetByTestId("unreachable").IsVisibleAsync(), $"{name}: no unreachable banner");
            var opacity = await tab.EvaluateAsync<double>("() => Number(getComputedStyle(document.getElementById('page')).opacity)");
            Assert.True(opacity < 1, $"{name}: the page's values are not marked stale while the server is unreachable (opacity {opacity})");
        }

        await restart.StartTheSecondRun(aheadOf, server => { });
        foreach (var (name, tab) in restart.Tabs)
        {
            await Expect(tab, "#message", "the console server restarted: plots and the event log start again");
            Assert.Equal(0, await tab.Locator("#message.error").CountAsync());
            Assert.False(await tab.GetByTestId("unreachable").IsVisibleAsync(), $"{name}: the unreachable banner stays");
        }

        // The operator's console took the role again, and the server agrees.
        await Expect(plots, "#message.ok", "this console is the operator again");
        await Expect(plots, "#role[data-role=operator]", "operator");
        Assert.True(await ServerSaysYou(plots), "the server does not name the plots page's console as the operator");

        // The plot: only the new run's samples, though its timeline is ahead of the old one's (no rows went backwards).
        await plots.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 20", null, new() { Timeout = 30_000 });
        var times = await PlottedTimes(plots);
        Assert.NotEmpty(times);
        Assert.All(times, t => Assert.True(t > aheadOf, string.Create(CultureInfo.InvariantCulture, $"a sample at {t:F3} s: from the old run (its last plotted sample was at {aheadOf:F3} s)")));

        // The event log: the new session's events only, read from its first; the old run's E-STOP gone.
        var status = restart.Tab("status");
        var first = restart.Second.EventsAfter(0)[0];
        await Expect(status, "[data-testid=event-log]", first.Message);
        var rows = await status.GetByTestId("event-log").Locator("tr").AllInnerTextsAsync();
        var known = restart.Second.EventsAfter(0).Select(Row).ToList();
        Assert.All(rows, r => Assert.Contains(Words(r), known));
        Assert.Equal(rows.Count, rows.Distinct().Count());
        Assert.DoesNotContain(rows, r => r.Contains("emergency stop", StringComparison.Ordinal));

        // The bus page and the surgeon's view show the new run's level (the old one ended in E-STOP).
        await Expect(restart.Tab("bus"), "[data-testid=run-level]", "run level PEDAL_UP");
        await Expect(restart.Tab("surgeon"), "[data-testid=run-level][data-level=PEDAL_UP]", "PEDAL_UP");
    }

    [Fact]
    public async Task When_another_console_takes_the_role_first_the_page_says_so_and_watches()
    {
        await using var restart = await Restart.Open(console, ["bus"]);
        var bus = restart.Tab("bus");
        await Expect(bus, "#role[data-role=operator]", "operator");

        var aheadOf = await restart.StopTheFirstRun();
        await restart.StartTheSecondRun(aheadOf, server => Assert.True(server.Operator.TryClaim("another-console")));

        await Expect(bus, "#message.error", "another console took the operator role first: this one watches");
        await Expect(bus, "#role[data-role=held]", "held by another console");
        Assert.False(await ServerSaysYou(bus));
        Assert.Equal("another-console", restart.Server.Operator.Holder);
    }

    /// <summary>An event as the status page's log row shows it: time, source, message (white space as the page collapses it).</summary>
    private static string Row(RobotControl.WebConsole.Session.EventEntry e) => Words(string.Create(CultureInfo.InvariantCulture, $"{e.TimeSeconds:F3} s {e.Source} {e.Message}"));

    private static string Words(string text) => Regex.Replace(text.Trim(), @"\s+", " ");

    /// <summary>What the server answers this page's console: /api/status operator.you.</summary>
    private static Task<bool> ServerSaysYou(IPage page) => page.EvaluateAsync<bool>(@"async () => {
        const headers = { 'X-Console-Client': sessionStorage.getItem('rc-console-client'), Authorization: `Bearer ${sessionStorage.getItem('rc-console-token')}` };
        return (await (await fetch('/api/status', { headers })).json()).operator.you;
    }");

    private static Task<IReadOnlyList<double>> PlottedTimes(IPage page) => ReplayPageTests.PlottedTimes(page);

    private static Task Expect(IPage page, string selector, string text) => PageTests.Expect(page, selector, text);

    /// <summary>
    /// Two runs of a console on one port, each its own session on the virtual robot (as <c>robotctl console</c> run
    /// twice with the same token), and the tabs of one browser on the first; the first tab takes the operator role.
    /// </summary>
    private sealed class Restart : IAsyncDisposable
    {
        private readonly IBrowserContext _context;
        private readonly LiveSession _first;
        private ConsoleServer? _firstServer;

        private bool _secondServes;

        private Restart(LiveSession first, LiveSession second, ConsoleServer server, IBrowserContext context)
        {
            _first = first;
            _firstServer = server;
            _context = context;
            Second = second;
            Server = server;
        }

        public List<(string Name, IPage Page)> Tabs { get; } = [];

        /// <summary>The second run's session: opened before the first, so its session time is ahead of the first's.</summary>
        public LiveSession Second { get; private set; }

        /// <summary>The server now serving.</summary>
        public ConsoleServer Server { get; private set; }

        public IPage Tab(string name) => Tabs.First(t => t.Name == name).Page;

        public static async Task<Restart> Open(ConsoleFixture console, string[] pages)
        {
            var second = ConsoleFixture.VirtualSession();
            await Task.Delay(1000);
            var session = ConsoleFixture.VirtualSession();
            var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
            var context = await console.Browser.NewContextAsync(new() { ViewportSize = new() { Width = 1400, Height = 900 }, AcceptDownloads = true });
            var restart = new Restart(session, second, server, context);
            foreach (var name in pages)
            {
                var tab = await context.NewPageAsync();
                await tab.GotoAsync(ConsoleFixture.PageUrl(server, name));
                if (name == "plots")
                {
                    await tab.GetByLabel("time window").SelectOptionAsync("60"); // the old samples stay in the window: a mix would show
                }

                restart.Tabs.Add((name, tab));
            }

            var operatorTab = restart.Tabs[0].Page;
            await operatorTab.Locator("#claim").ClickAsync();
            await Expect(operatorTab, "#role[data-role=operator]", "operator");
            if (pages.Length > 1)
            {
                await Expect(restart.Tab(pages[^1]), "#role[data-role=held]", "held by another console");
            }

            return restart;
        }

        /// <summary>
        /// Ends the first run after an E-STOP (an event the second run never has) and once the plot has samples;
        /// returns the time of the last sample the first run streamed to the plot (0 without a plots tab).
        /// </summary>
        public async Task<double> StopTheFirstRun()
        {
            var plots = Tabs.FirstOrDefault(t => t.Name == "plots").Page;
            if (plots is not null)
            {
                await plots.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 20", null, new() { Timeout = 30_000 });
            }

            using (var http = ConsoleFixture.Client(Server, "stopper"))
            {
                (await http.PostAsync("api/estop", null)).EnsureSuccessStatusCode();
            }

            if (Tabs.Any(t => t.Name == "status"))
            {
                await Expect(Tab("status"), "[data-testid=event-log]", "emergency stop");
            }

            await _firstServer!.DisposeAsync();
            _firstServer = null;
            _first.Dispose();
            foreach (var (_, tab) in Tabs)
            {
                await tab.GetByTestId("unreachable").WaitForAsync(new() { State = WaitForSelectorState.Visible, Timeout = 15_000 });
            }

            return plots is null ? 0 : (await PlottedTimes(plots)).DefaultIfEmpty(0).Max();
        }

        /// <summary>
        /// Serves the second run on the first's port and token. The pages' requests wait until its session time is a
        /// second past <paramref name="aheadOf"/> (so its samples lie ahead of the old ones; it was opened first, so this
        /// is normally so already) and <paramref name="before"/> has run on the new server.
        /// </summary>
        public async Task StartTheSecondRun(double aheadOf, Action<ConsoleServer> before)
        {
            var open = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            Server = await ConsoleServer.StartAsync(Second, new ConsoleServerOptions
            {
                Bind = BindAddress.Parse($"127.0.0.1:{Server.BaseUrl.Port}"),
                Token = Server.Token,
                First = async (HttpContext http, RequestDelegate next) =>
                {
                    await open.Task.ConfigureAwait(false);
                    await next(http).ConfigureAwait(false);
                },
            });
            _secondServes = true;
            var waited = Stopwatch.StartNew();
            while (Second.Status.SessionSeconds < aheadOf + 1)
            {
                Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), $"the second run's session time is {Second.Status.SessionSeconds} s after 60 s");
                await Task.Delay(50);
            }

            before(Server);
            open.SetResult();
        }

        public async ValueTask DisposeAsync()
        {
            await _context.CloseAsync();
            if (_firstServer is not null)
            {
                await _firstServer.DisposeAsync();
                _first.Dispose();
            }
            else if (_secondServes)
            {
                await Server.DisposeAsync();
            }

            Second.Dispose();
        }
    }
}
