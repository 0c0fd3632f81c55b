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

/// <summary>axe-core, the console front end's dev dependency, as the page tests run it.</summary>
public static class AxeCheck
{
    /// <summary>axe-core's script in the front end's node_modules (let past the console's Content-Security-Policy by a context with <c>BypassCSP</c>).</summary>
    public static string ScriptPath { get; } = RepositoryPaths.Of("src/RobotControl.Console/web/node_modules/axe-core/axe.min.js");

    /// <summary>A function for the page to evaluate: axe on the whole document, its serious and critical violations as lines.</summary>
    public const string SeriousViolations = @"async () => {
        const result = await axe.run(document, { resultTypes: ['violations'] });
        return result.violations.filter((v) => v.impact === 'serious' || v.impact === 'critical')
            .map((v) => `${v.impact} ${v.id} (${v.help}): ${v.nodes.slice(0, 4).map((n) => n.target.join(' ')).join(', ')}`);
    }";
}
