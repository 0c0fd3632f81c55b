using System.Globalization;
using Microsoft.Playwright;
using RobotControl.WebConsole.Server;
using Xunit.Abstractions;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>
/// Start-up: each page, loaded fresh (a new browser context: cold cache, no stored state), marks its first useful value
/// (bus: a module card with a position; plots: the first plotted sample; 3D: the first pose; status: the run status
/// table; surgeon: the run-level word; the editor, in its own collection: the graph drawn) as <c>data-first-value</c> on
/// the page element, the time since navigation in ms, with the performance mark <c>first-value</c>. Asserted: every load
/// marks it. The times are printed (median of <see cref="Loads"/> per page; docs/performance.md), never asserted: a
/// loaded test run would fail a timed assertion.
/// </summary>
[Collection(ConsoleCollection.Name)]
public sealed class StartUpTests(ConsoleFixture console, ITestOutputHelper output)
{
    /// <summary>Fresh loads per page.</summary>
    public const int Loads = 5;

    [Fact]
    public async Task Every_page_marks_its_first_useful_value_and_the_times_are_printed()
    {
        var times = await Measure(console.Browser, console.Server, ["bus", "plots", "view3d", "status", "surgeon"], output);
        Assert.All(times, t => Assert.Equal(Loads, t.Value.Count));
    }

    /// <summary><see cref="Loads"/> fresh loads of each of <paramref name="pages"/>, round robin; prints each page's times and median.</summary>
    internal static async Task<Dictionary<string, List<double>>> Measure(IBrowser browser, ConsoleServer server, string[] pages, ITestOutputHelper output)
    {
        var times = pages.ToDictionary(p => p, _ => new List<double>());
        for (var load = 0; load < Loads; load++)
        {
            foreach (var name in pages)
            {
                times[name].Add(await FirstValueMs(browser, server, name));
            }
        }

        var loadAverage = File.Exists("/proc/loadavg") ? File.ReadAllText("/proc/loadavg").Split(' ')[0] : "unknown";
        output.WriteLine($"first useful value, ms from navigation start, {Loads} fresh loads per page (headless Chromium, load average {loadAverage}):");
        foreach (var (name, ms) in times)
        {
            var sorted = ms.Order().ToList();
            output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"  {name,-8} median {sorted[sorted.Count / 2],7:F0} ms  (loads: {string.Join(", ", ms.Select(t => t.ToString("F0", CultureInfo.InvariantCulture)))})"));
        }

        return times;
    }

    /// <summary>One fresh load of <paramref name="name"/>: the page's own mark of its first value (ms since navigation start).</summary>
    private static async Task<double> FirstValueMs(IBrowser browser, ConsoleServer server, string name)
    {
        var context = await browser.NewContextAsync(new() { ViewportSize = new() { Width = 1400, Height = 900 } });
        try
        {
            var page = await context.NewPageAsync();
            await page.GotoAsync(ConsoleFixture.PageUrl(server, name));
            var marked = page.Locator($"#page[data-page={name}][data-first-value]");
            await marked.WaitForAsync(new() { State = WaitForSelectorState.Attached, Timeout = 60_000 });
            var at = double.Parse((await marked.GetAttributeAsync("data-first-value"))!, CultureInfo.InvariantCulture);
            var mark = await page.EvaluateAsync<double>("() => performance.getEntriesByName('first-value', 'mark')[0]?.startTime ?? -1");
            Assert.True(mark >= 0, $"{name}: no performance mark 'first-value'");
            Assert.True(at > 0, $"{name}: first value marked at {at} ms");
            return at;
        }
        finally
        {
            await context.CloseAsync();
        }
    }
}
