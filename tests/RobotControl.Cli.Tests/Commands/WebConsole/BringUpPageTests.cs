using System.Net.Http.Headers;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Microsoft.Playwright;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Cli.Tests.Commands.Commission;
using RobotControl.Cli.Tests.Commands.Run;
using RobotControl.Modules;
using RobotControl.TestSupport;

namespace RobotControl.Cli.Tests.Commands.WebConsole;

/// <summary>
/// <c>robotctl console --bring-up</c> in a process of its own over <c>bus-sim --factory --unit-variation</c> (the real
/// firmware behind a pty), its Bring-up page in real headless Chromium: a factory box commissioned from the page
/// (each module connected as the page says) and one module's pots calibrated with the fixture confirmed by Continue,
/// the unit file as the CLI writes it; a watching console cannot start a step, but its STOP and its status bar's
/// E-STOP each stop a calibration mid-sweep with the motors off (read back on the simulator), and the page says so.
/// </summary>
[Collection(RunProcess.Collection)]
public sealed partial class BringUpPageTests : IDisposable
{
    private static readonly TimeSpan Patience = RunProcess.Patience;
    private static readonly float Calibration = (float)TimeSpan.FromMinutes(5).TotalMilliseconds;
    private static readonly float Wait = (float)Patience.TotalMilliseconds;
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public async Task A_factory_box_is_commissioned_and_a_module_calibrated_from_the_page_and_the_unit_file_is_what_the_cli_writes()
    {
        using var sim = FactoryBench.StartSim(out var transport);
        using var console = Serve(transport, "lb-0301", out var url);
        await using var browser = await Browser.LaunchAsync();
        var page = await browser.Open(url, operate: true);

        await page.GetByTestId("bringup-poll").CheckAsync();
        await page.GetByTestId("bringup-commission").ClickAsync();
        var log = page.GetByTestId("bringup-log");
        for (var k = 1; k <= 6; k++)
        {
            await Assertions.Expect(log).ToContainTextAsync($"connect module {k} of 6 (", new() { Timeout = Wait });
            var id = Regex.Match(await log.InnerTextAsync(), $@"connect module {k} of 6 \([^)]*, id (\d+)\)").Groups[1].Value;
            sim.Type($"connect {id}");
            sim.WaitFor($"connected module {id} ", Patience);
        }

        await Assertions.Expect(page.GetByTestId("bringup-result")).ToHaveTextAsync($"unit lb-0301 commissioned: 6 modules ({UnitPath("lb-0301")})", new() { Timeout = Wait });
        await Assertions.Expect(page.GetByTestId("bringup-module-11")).ToHaveTextAsync("commissioned");
        var robot = SimulatorProcess.Robot;
        var modules = Unit("lb-0301")["modules"]!.AsArray();
        Assert.Equal(new[] { 2, 3, 11, 12, 13, 1 }, modules.Select(m => (int)m!["id"]!));
        foreach (var m in modules)
        {
            var module = robot.Modules.Modules.Single(d => d.Id == (int)m!["id"]!);
            var expected = ModuleParameters.For(robot, module, ControlTable.Firmware).Where(p => p.Field.Name != "baud_rate").Select(p => Robot.Commissioning.UnitFile.Key(p.Field, p.Motor)).Order(StringComparer.Ordinal);
            Assert.Equal(expected, m!["parameters"]!.AsObject().Select(p => p.Key).Order(StringComparer.Ordinal));
            Assert.Equal((int)ControlTable.Firmware["firmware_version"].Default, (int)m["firmware_version"]!);
        }

        var commissioned = Parameters("lb-0301", 2);
        await page.GetByTestId("bringup-module").SelectOptionAsync("2");
        await page.GetByTestId("bringup-calibrate").ClickAsync();
        await Assertions.Expect(page.GetByTestId("bringup-prompt-text")).ToHaveTextAsync(
            "module 2 (right upper arm): put the arm in its fixture pose (right.elbow 75.0 deg: every joint at mid-range, the jaw half open), keep clear of it, then press Continue", new() { Timeout = Wait });
        Assert.DoesNotContain("sweeping", await log.InnerTextAsync(), StringComparison.Ordinal); // nothing moves before Continue
        await page.GetByTestId("bringup-continue").ClickAsync();
        await Assertions.Expect(page.GetByTestId("bringup-result")).ToContainTextAsync("unit lb-0301: 1 pot calibrated and verified, motors off (read back)", new() { Timeout = Calibration });
        await Assertions.Expect(page.GetByTestId("bringup-pot-right.elbow")).ToContainTextAsync("calibrated and verified, worst ");
        await Assertions.Expect(page.GetByTestId("bringup-pot-left.elbow")).ToHaveTextAsync("not calibrated");
        await Assertions.Expect(page.GetByTestId("bringup-prompt")).ToBeHiddenAsync(); // no question once the step is done
        if (Environment.GetEnvironmentVariable("CONSOLE_SCREENSHOTS") is { Length: > 0 } dir)
        {
            await page.ScreenshotAsync(new() { Path = Path.Combine(dir, "bringup.png") });
        }

        var elbow = Unit("lb-0301")["modules"]!.AsArray().Single(m => (int)m!["id"]! == 2)!;
        Assert.True((bool)elbow["pot_calibration"]!["right.elbow"]!["verified"]!);
        var calibrated = Parameters("lb-0301", 2);
        Assert.Equal(commissioned.Keys.Order(StringComparer.Ordinal), calibrated.Keys.Order(StringComparer.Ordinal));
        var changed = calibrated.Keys.Where(k => calibrated[k] != commissioned[k]).ToList();
        Assert.All(changed, k => Assert.StartsWith("pot_cal_", k, StringComparison.Ordinal)); // the fitted table replaced the design curve's, nothing else
        Assert.Contains(changed, k => k.StartsWith("pot_cal_raw", StringComparison.Ordinal));

        // The CLI reads the unit the page wrote as its own: every module as commissioned, the pot table as calibrated.
        var discover = Cli.Run("discover", transport, "--robot", FactoryBench.Robot, "--unit", "lb-0301", "--units", _units, "--margin-ms", "50");
        Assert.True(discover.Code == 0, discover.Output + discover.Error);
        Assert.Contains("unit lb-0301: 6 modules as commissioned", discover.Output, StringComparison.Ordinal);
        Assert.Contains("pot_cal values are unit lb-0301's calibrated pot tables", discover.Output, StringComparison.Ordinal);
    }

    [Fact]
    public async Task A_watching_console_cannot_start_a_step_but_its_STOP_and_its_E_STOP_stop_a_calibration_mid_sweep_with_the_motors_off()
    {
        using var sim = FactoryBench.StartSim(out var transport);
        FactoryBench.Commission(sim, transport, "lb-0302", _units);
        using var console = Serve(transport, "lb-0302", out var url);
        await using var browser = await Browser.LaunchAsync();
        var operating = await browser.Open(url, operate: true, axe: true);
        var watching = await browser.Open(url, operate: false);

        await Assertions.Expect(watching.GetByTestId("bringup-calibrate")).ToBeDisabledAsync();
        await Assertions.Expect(watching.GetByTestId("bringup-commission")).ToBeDisabledAsync();
        await Assertions.Expect(watching.GetByTestId("bringup-stop")).ToBeEnabledAsync();
        using (var http = new HttpClient { BaseAddress = new Uri(url.GetLeftPart(UriPartial.Authority)) })
        {
            http.DefaultRequestHeaders.Authorization = new AuthenticationHeaderValue("Bearer", Token().Match(url.Query).Groups[1].Value);
            http.DefaultRequestHeaders.Add("X-Console-Client", "a-watching-script");
            var refused = await http.PostAsync(new Uri("api/bringup/calibrate", UriKind.Relative), new StringContent("{}", new MediaTypeHeaderValue("application/json")));
            Assert.Equal(System.Net.HttpStatusCode.Forbidden, refused.StatusCode);
            Assert.Contains("another console holds the operator role; this one watches", await refused.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        }

        var sweeping = operating.GetByTestId("bringup-log").Locator("li", new() { HasTextString = "right.elbow: sweeping its range" });
        foreach (var (stop, round) in new[] { ("bringup-stop", 1), ("bar-estop", 2) })
        {
            await operating.GetByTestId("bringup-module").SelectOptionAsync("2");
            await operating.GetByTestId("bringup-redo").CheckAsync();
            await operating.GetByTestId("bringup-calibrate").ClickAsync();
            await Assertions.Expect(operating.GetByTestId("bringup-prompt-text")).ToContainTextAsync("put the arm in its fixture pose", new() { Timeout = Wait });
            await operating.GetByTestId("bringup-continue").ClickAsync();
            await Assertions.Expect(operating.Locator("#message")).ToHaveTextAsync("calibrate: continuing", new() { Timeout = Wait });
            await Assertions.Expect(sweeping).ToHaveCountAsync(round, new() { Timeout = Wait });
            await watching.GetByTestId(stop).ClickAsync();
            foreach (var page in new[] { watching, operating })
            {
                var result = page.GetByTestId("bringup-result");
                await Assertions.Expect(result).ToHaveTextAsync("stopped: module 2 (right upper arm)'s motors are off (read back); run calibrate pots again to continue (motors calibrated and verified are kept)", new() { Timeout = Wait });
                await Assertions.Expect(result).ToHaveAttributeAsync("role", "alert");
            }

            await Assertions.Expect(watching.GetByTestId("bringup-state")).ToHaveTextAsync("Calibrate pots: stopped", new() { Timeout = Wait });
            Assert.Equal(round, await sweeping.CountAsync()); // stopped in that sweep
            Assert.Equal(0, TorqueOf(transport, 2)); // the step closed the bus: the simulator's module reads back off
            await Assertions.Expect(operating.GetByTestId("bar-motors")).ToHaveTextAsync("motors off", new() { Timeout = Wait });
        }

        Assert.All(Unit("lb-0302")["modules"]!.AsArray(), m => Assert.Null(m!["pot_calibration"]));
        Assert.Empty(await Browser.SeriousViolations(operating)); // the page with its table, log and stop line
    }

    /// <summary>Starts the bring-up console on <paramref name="transport"/> for <paramref name="unit"/>; <paramref name="url"/> is the page it prints.</summary>
    private RunProcess Serve(string transport, string unit, out Uri url)
    {
        var console = new RunProcess("console", "--bring-up", FactoryBench.Robot, "--transport", transport, "--unit", unit, "--units", _units, "--bind", "127.0.0.1:0", "--margin-ms", "50");
        url = new Uri(PageUrl().Match(console.WaitFor("#bringup", Patience)).Value);
        return console;
    }

    private static int TorqueOf(string transport, byte id)
    {
        using var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) });
        var torque = new byte[1];
        Assert.True(client.Read(id, ControlTable.Firmware["torque_enable"].At(0), torque).Succeeded);
        return torque[0];
    }

    private string UnitPath(string unit) => Path.Combine(_units, unit + ".json");

    private Dictionary<string, long> Parameters(string unit, int id) =>
        Unit(unit)["modules"]!.AsArray().Single(m => (int)m!["id"]! == id)!["parameters"]!.AsObject().ToDictionary(p => p.Key, p => (long)p.Value!);

    private JsonNode Unit(string unit) => JsonNode.Parse(File.ReadAllText(UnitPath(unit)))!;

    [GeneratedRegex(@"http://\S+#bringup")]
    private static partial Regex PageUrl();

    [GeneratedRegex(@"token=([0-9a-f]+)")]
    private static partial Regex Token();

    /// <summary>Playwright with Debian's headless Chromium; each page opened in a context of its own (a console of its own).</summary>
    private sealed class Browser : IAsyncDisposable
    {
        private readonly IPlaywright _playwright;
        private readonly IBrowser _browser;

        private Browser(IPlaywright playwright, IBrowser browser)
        {
            _playwright = playwright;
            _browser = browser;
        }

        public static async Task<Browser> LaunchAsync()
        {
            var playwright = await Playwright.CreateAsync();
            return new Browser(playwright, await playwright.Chromium.LaunchAsync(new() { ExecutablePath = DebianChromium.Path, Headless = true, Args = DebianChromium.Args }));
        }

        /// <summary>
        /// A console on <paramref name="url"/>: with <paramref name="operate"/>, it takes the operator role; without, it
        /// watches the operator opened before it. With <paramref name="axe"/>, the browser lets the test's copy of
        /// axe-core past the console's Content-Security-Policy (<see cref="SeriousViolations"/>).
        /// </summary>
        public async Task<IPage> Open(Uri url, bool operate, bool axe = false)
        {
            var page = await (await _browser.NewContextAsync(new() { ViewportSize = new() { Width = 1920, Height = 1080 }, BypassCSP = axe })).NewPageAsync();
            await page.GotoAsync(url.ToString());
            if (operate)
            {
                await page.Locator("#claim").ClickAsync();
            }

            await Assertions.Expect(page.Locator("#role")).ToHaveTextAsync(operate ? "operator" : "watching: held by another console", new() { Timeout = Wait });
            return page;
        }

        /// <summary>axe-core (the front end's dev dependency) on <paramref name="page"/>: its serious and critical violations.</summary>
        public static async Task<string[]> SeriousViolations(IPage page)
        {
            await page.AddScriptTagAsync(new() { Path = AxeCheck.ScriptPath });
            return await page.EvaluateAsync<string[]>(AxeCheck.SeriousViolations);
        }

        public async ValueTask DisposeAsync()
        {
            await _browser.DisposeAsync();
            _playwright.Dispose();
        }
    }
}
