using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>axe-core (the front end's dev dependency, from its node_modules) on every page in real headless Chromium: no serious or critical violation.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class AccessibilityTests(ConsoleFixture console)
{
    private static readonly string AxeScript = Path.Combine(ConsoleFixture.RepoRoot, "src", "RobotControl.Console", "web", "node_modules", "axe-core", "axe.min.js");

    [Theory]
    [MemberData(nameof(EveryPage))]
    public async Task Axe_finds_no_serious_or_critical_violation(string name)
    {
        console.ReleaseOperator();
        // The console's Content-Security-Policy allows only its own scripts: the test's copy of axe is let in by the browser context.
        var context = await console.Browser.NewContextAsync(new() { ViewportSize = new() { Width = 1920, Height = 1080 }, BypassCSP = true });
        try
        {
            var page = await context.NewPageAsync();
            await page.GotoAsync(ConsoleFixture.PageUrl(console.Server, name));
            await page.Locator("#role").Filter(new() { HasTextString = "watching" }).WaitForAsync();
            await page.WaitForTimeoutAsync(1500);
            await page.AddScriptTagAsync(new() { Path = AxeScript });
            var violations = await page.EvaluateAsync<string[]>(@"async () => {
                const result = await axe.run(document, { resultTypes: ['violations'] });
                return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
                    .map((v) => `${v.impact} ${v.id} (${v.help}): ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join(', ')}`);
            }");
            Assert.True(violations.Length == 0, $"{name}: {string.Join("\n", violations)}");
        }
        finally
        {
            await context.CloseAsync();
        }
    }

    public static TheoryData<string> EveryPage() => [.. StatusBarTests.Pages];
}
