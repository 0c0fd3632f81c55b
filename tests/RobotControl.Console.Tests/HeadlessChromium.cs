using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests;

/// <summary>Playwright with Debian's headless Chromium (<see cref="ConsoleFixture.LaunchChromiumAsync"/>), closed together.</summary>
public sealed class HeadlessChromium : IAsyncDisposable
{
    private readonly IPlaywright _playwright;

    private HeadlessChromium(IPlaywright playwright, IBrowser browser)
    {
        _playwright = playwright;
        Browser = browser;
    }

    public IBrowser Browser { get; }

    public static async Task<HeadlessChromium> LaunchAsync()
    {
        var playwright = await Playwright.CreateAsync();
        return new HeadlessChromium(playwright, await ConsoleFixture.LaunchChromiumAsync(playwright));
    }

    public async ValueTask DisposeAsync()
    {
        await Browser.DisposeAsync();
        _playwright.Dispose();
    }
}
