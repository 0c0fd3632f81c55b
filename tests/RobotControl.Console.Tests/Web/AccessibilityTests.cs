using Microsoft.Playwright;
using RobotControl.TestSupport;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>axe-core (the front end's dev dependency, from its node_modules) on every page in real headless Chromium: no serious or critical violation.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class AccessibilityTests(ConsoleFixture console)
{
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
            await page.AddScriptTagAsync(new() { Path = AxeCheck.ScriptPath });
            var violations = await page.EvaluateAsync<string[]>(AxeCheck.SeriousViolations);
            Assert.True(violations.Length == 0, $"{name}: {string.Join("\n", violations)}");
        }
        finally
        {
            await context.CloseAsync();
        }
    }

    public static TheoryData<string> EveryPage() => [.. StatusBarTests.Pages];
}
