namespace RobotControl.TestSupport;

/// <summary>The browser the page tests drive through Playwright: Debian's headless Chromium and its switches.</summary>
public static class DebianChromium
{
    /// <summary>Where Debian installs it.</summary>
    public const string Path = "/usr/bin/chromium";

    /// <summary>Chromium's switches: WebGL through SwiftShader, and Chromium's fake capture device, granted without asking (the surgeon's video panel).</summary>
    public static IReadOnlyList<string> Args { get; } =
    [
        "--no-sandbox", "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
        "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
        "--use-fake-device-for-media-stream", "--use-fake-ui-for-media-stream",
    ];
}
