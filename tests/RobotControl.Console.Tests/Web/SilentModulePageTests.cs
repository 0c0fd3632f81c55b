using Microsoft.Playwright;
using RobotControl.Host.Harness;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>
/// A module that stops answering is not shown as healthy on the bus page (real headless Chromium): its card says it
/// does not answer and how many polls it missed, its motors' torque reads unknown and their values are marked as the
/// last it gave, while the modules that answer still read normally.
/// </summary>
public sealed class SilentModulePageTests
{
    [Fact]
    public async Task A_module_that_stops_answering_is_shown_as_not_answering_with_its_torque_unknown()
    {
        using var session = ConsoleFixture.VirtualSession(FaultInjection.Parse("silent=left.forearm@2s"));
        await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
        await using var chromium = await HeadlessChromium.LaunchAsync();
        var page = await (await chromium.Browser.NewContextAsync()).NewPageAsync();
        await page.GotoAsync(ConsoleFixture.PageUrl(server, "bus"));

        var silent = page.Locator("[data-controller=\"13\"]");
        var answering = page.Locator("[data-controller=\"11\"]");
        await Assertions.Expect(answering.Locator("[data-field=present]")).ToHaveTextAsync("present", new() { Timeout = 60_000 });
        await Assertions.Expect(silent.Locator("[data-field=present]")).ToContainTextAsync("NOT ANSWERING (", new() { Timeout = 60_000 });
        await Assertions.Expect(silent).ToHaveClassAsync(new System.Text.RegularExpressions.Regex("missing"));
        foreach (var torque in await silent.Locator("[data-field=torque]").AllAsync())
        {
            await Assertions.Expect(torque).ToHaveTextAsync("unknown: no answer");
        }

        foreach (var current in await silent.Locator("[data-field=current]").AllAsync())
        {
            await Assertions.Expect(current).ToContainTextAsync("(last)");
        }

        Assert.DoesNotContain("unknown", await answering.Locator("[data-field=torque]").First.TextContentAsync() ?? string.Empty, StringComparison.Ordinal);
        Assert.True(session.Controllers.Single(c => c.Id == 13).MissedReplies > 0);
        Assert.All(session.Controllers.Where(c => c.Id != 13), c => Assert.Equal(0, c.MissedReplies));
    }
}
