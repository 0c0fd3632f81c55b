using System.Net.Http.Json;
using System.Text.Json;
using Microsoft.Playwright;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Surgeon;

/// <summary>The surgeon's view in real headless Chromium (fake capture device) against its own virtual-robot console.</summary>
[Collection(SurgeonCollection.Name)]
public sealed class SurgeonPageTests(SurgeonFixture console)
{
    [Fact]
    public async Task The_scripted_pedal_changes_the_run_level_shown()
    {
        var page = await Open(console.Server, operate: false);
        foreach (var level in new[] { "PEDAL_DOWN", "PEDAL_UP", "PEDAL_DOWN", "PEDAL_UP" })
        {
            // The attribute and the text shown are checked together: the scripted pedal moves on by itself, so a
            // second read could already see the next level.
            var shown = page.Locator($"[data-testid=run-level][data-level={level}]").Filter(new() { HasTextString = level });
            await shown.WaitForAsync(new() { Timeout = 20000 });
            if (level == "PEDAL_DOWN")
            {
                await Expect(page.GetByTestId("pedal-state-pedals.pedal1"), "PRESSED");
            }
        }

        await Expect(page.GetByTestId("pedal-pedals.pedal1"), "run level (pedal)");
        await Expect(page.GetByTestId("pedal-pedals.pedal2"), "right clutch");
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task The_view_fills_a_1920x1080_screen_with_the_arms_video_run_level_and_hands()
    {
        var page = await Open(console.Server, operate: true);
        await page.WaitForFunctionAsync("() => document.querySelector('video[data-testid=endoscope]').videoWidth > 0");
        await page.WaitForTimeoutAsync(600);

        // Nothing scrolls: the view fits the screen, and the 3D view is the largest panel.
        Assert.True(await page.EvaluateAsync<bool>("() => document.documentElement.scrollHeight <= innerHeight && document.documentElement.scrollWidth <= innerWidth"), "the surgeon's view scrolls at 1920x1080");
        var canvas = await page.GetByTestId("surgeon-3d").BoundingBoxAsync();
        Assert.True(canvas is { Width: > 1000, Height: > 700 }, $"3D view {canvas?.Width}x{canvas?.Height}");
        var drawn = await page.EvaluateAsync<int>(@"() => {
            const c = document.querySelector('canvas[data-testid=surgeon-3d]');
            const t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
            const g = t.getContext('2d'); g.drawImage(c, 0, 0);
            const d = g.getImageData(0, 0, t.width, t.height).data;
            let n = 0; for (let i = 0; i < d.length; i += 4) if (Math.abs(d[i] - d[0]) + Math.abs(d[i + 1] - d[1]) + Math.abs(d[i + 2] - d[2]) > 30) n++;
            return n; }");
        Assert.True(drawn > 5000, $"only {drawn} pixels of the 3D view differ from its background");
        await page.Locator("[data-testid=run-level][data-level=PEDAL_DOWN]").WaitForAsync(new() { Timeout = 20000 });

        // Legible from 2 m: the run level, the E-STOP label and each arm's state at least 48 px.
        foreach (var selector in new[] { "[data-testid=run-level]", "[data-testid=surgeon-estop]", "[data-testid=arm-left]", "[data-testid=arm-right]" })
        {
            var px = await page.Locator(selector).EvaluateAsync<double>("e => parseFloat(getComputedStyle(e).fontSize)");
            Assert.True(px >= 48, $"{selector}: {px} px");
        }

        Assert.Equal("FOLLOWING", await page.GetByTestId("arm-right").TextContentAsync());
        if (Environment.GetEnvironmentVariable("CONSOLE_SCREENSHOTS") is { Length: > 0 } dir)
        {
            Directory.CreateDirectory(dir);
            await page.ScreenshotAsync(new() { Path = Path.Combine(dir, "surgeon-view.png") });
        }

        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task The_E_STOP_button_trips_the_supervisor_and_the_motors_go_off()
    {
        var page = await Open(console.Server, operate: true);
        await Expect(page.GetByTestId("surgeon-estop"), "Space / Esc");
        await page.GetByTestId("surgeon-estop").ClickAsync();
        await AssertStoppedAndRecover(page);
    }

    [Fact]
    public async Task The_E_STOP_shortcut_trips_the_supervisor_and_the_motors_go_off()
    {
        var page = await Open(console.Server, operate: true);
        await page.Keyboard.PressAsync("Space");
        await AssertStoppedAndRecover(page);
    }

    [Fact]
    public async Task The_video_panel_shows_the_fake_capture_stream()
    {
        var page = await Open(console.Server, operate: false);
        await page.WaitForFunctionAsync("() => { const v = document.querySelector('video[data-testid=endoscope]'); return v && v.videoWidth > 0 && !v.paused && v.readyState >= 2; }", null, new() { Timeout = 15000 });
        var time = await page.EvalOnSelectorAsync<double>("video[data-testid=endoscope]", "v => v.currentTime");
        await page.WaitForTimeoutAsync(500);
        Assert.True(await page.EvalOnSelectorAsync<double>("video[data-testid=endoscope]", "v => v.currentTime") > time, "the video is not playing");
        Assert.True(await page.Locator("[data-testid=video-device] option").CountAsync() >= 1);
        var remembered = await page.EvaluateAsync<string?>("() => localStorage.getItem('rc-endoscope-device')");
        Assert.False(string.IsNullOrEmpty(remembered));
        Assert.Equal(string.Empty, (await page.GetByTestId("video-note").TextContentAsync())?.Trim());
        await page.Context.CloseAsync();
    }

    [Fact]
    public async Task The_scale_changes_only_while_the_clutch_is_held()
    {
        var page = await Open(console.Server, operate: true);
        await Expect(page.GetByTestId("clutch-right"), "released");
        Assert.True(await page.GetByTestId("scale-up-right").IsDisabledAsync());
        await Expect(page.GetByTestId("scale-hint-right"), "hold the clutch to change the scale");

        await Expect(page.GetByTestId("clutch-right"), "HELD", 20000);
        var before = await Scale();
        await page.GetByTestId("scale-up-right").ClickAsync();
        await Expect(page.Locator("#message.ok"), "right scale factor");
        Assert.Equal(before + 0.1, await Scale(), 6);
        await Expect(page.GetByTestId("scale-right"), (before + 0.1).ToString("0.00", System.Globalization.CultureInfo.InvariantCulture));
        await page.Context.CloseAsync();

        async Task<double> Scale()
        {
            using var http = await console.Client("scale-reader", operate: false);
            var view = await http.GetFromJsonAsync<JsonElement>("api/surgeon");
            return view.GetProperty("hands").EnumerateArray().Single(h => h.GetProperty("arm").GetString() == "right").GetProperty("scale").GetDouble();
        }
    }

    [Fact]
    public async Task An_injected_fault_shows_in_plain_words_with_the_detail_one_click_away()
    {
        var folder = Path.Combine(Path.GetTempPath(), $"rc-surgeon-fault-{Guid.NewGuid():N}");
        Directory.CreateDirectory(folder);
        try
        {
            SurgeonFixture.WriteRobotAndGraph(folder);
            using var session = new LiveSession(new LiveSessionOptions
            {
                GraphPath = Path.Combine(folder, "surgeon.json"),
                Catalog = ConsoleFixture.Catalog(),
                Virtual = true,
                Inject = Host.Harness.FaultInjection.Parse("silent=left.forearm@10s"),
            });
            await using var server = await ConsoleServer.StartAsync(session, BindAddress.Parse("127.0.0.1:0"), null);
            var page = await Open(server, operate: false);
            await Expect(page.GetByTestId("no-faults"), "No faults");
            var fault = page.GetByTestId("fault");
            await Expect(fault, "Left forearm module stopped answering — motors off", 20000);
            await Expect(page.GetByTestId("run-level"), "E-STOP");
            // The silent module's trips: first soft (arms holding) at 10 ms, then, still silent at the modules' torque-off
            // stage, the motors off. The second's detail opens on a click.
            await Expect(page.Locator(".fault").Filter(new() { HasTextString = "Left forearm module stopped answering — arms holding, press the pedal again" }).GetByTestId("fault"), "Left forearm module stopped answering — arms holding, press the pedal again");
            var entry = page.Locator(".fault").Filter(new() { HasTextString = "Left forearm module stopped answering — motors off" });
            Assert.False(await entry.GetByTestId("fault-detail").IsVisibleAsync());
            await entry.GetByTestId("fault").ClickAsync();
            Assert.True(await entry.GetByTestId("fault-detail").IsVisibleAsync());
            var detail = await entry.GetByTestId("fault-detail").TextContentAsync() ?? string.Empty;
            Assert.Contains("check module_silent · left.forearm", detail, StringComparison.Ordinal);
            var stage = Definitions.Loading.RobotLoader.Load(Path.Combine(folder, "lb-estop-off.json")).Modules.WatchdogOffMs; // the modules' torque-off stage
            Assert.Contains($"limit {stage} ms", detail, StringComparison.Ordinal);
            Assert.Contains("action torque_off", detail, StringComparison.Ordinal);

            // The faulted arm, and only it, is marked on its hand card and in 3D; the other shows what the stop did to it.
            await page.Locator("[data-testid=arm-left][data-state=fault]").WaitForAsync();
            Assert.Equal("FAULT", await page.GetByTestId("arm-left").TextContentAsync());
            Assert.StartsWith("Left forearm module stopped answering", await page.GetByTestId("arm-why-left").TextContentAsync(), StringComparison.Ordinal);
            Assert.Equal("STOPPED", await page.GetByTestId("arm-right").TextContentAsync());
            Assert.Equal("left", await page.GetByTestId("surgeon-3d").GetAttributeAsync("data-faulted"));
            Assert.Contains("faulted", await page.GetByTestId("arm-label-left").GetAttributeAsync("class") ?? string.Empty, StringComparison.Ordinal);
            Assert.DoesNotContain("faulted", await page.GetByTestId("arm-label-right").GetAttributeAsync("class") ?? string.Empty, StringComparison.Ordinal);
            await page.Context.CloseAsync();
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    /// <summary>The page shows E-STOP, the supervisor is at E_STOP and every virtual module reports its motors off; then reset and torque on.</summary>
    private async Task AssertStoppedAndRecover(IPage page)
    {
        await page.Locator("[data-testid=run-level][data-level=E_STOP]").WaitForAsync(new() { Timeout = 10000 });
        Assert.Equal("E_STOP", console.Session.Status.RobotState);
        await Expect(page.GetByTestId("fault"), "Emergency stop pressed — motors off");
        using var http = await console.Client("estop-checker", operate: false);
        await SurgeonFixture.Until(() => !console.Session.Status.TorqueOn, "the robot layer to turn the motors off");

        // The modules' own torque_enable, polled over the bus (each module five times a second).
        await Task.Delay(1500);
        var controllers = await http.GetFromJsonAsync<JsonElement>("api/controllers");
        var motors = controllers.EnumerateArray().SelectMany(c => c.GetProperty("motors").EnumerateArray()).ToList();
        Assert.NotEmpty(motors);
        Assert.All(motors, m => Assert.False(m.GetProperty("torqueOn").GetBoolean(), $"{m.GetProperty("name")} still has torque"));

        // Back from the view itself: Reset (shown at E-STOP only), then Home the arms (at INIT only), each confirmed.
        var asked = new List<string>();
        page.Dialog += (_, dialog) => { asked.Add(dialog.Message); _ = dialog.AcceptAsync(); };
        Assert.True(await page.GetByTestId("surgeon-home").IsHiddenAsync());
        await page.GetByTestId("surgeon-reset").ClickAsync();
        await page.Locator("[data-testid=run-level][data-level=INIT]").WaitForAsync(new() { Timeout = 10000 });
        Assert.True(await page.GetByTestId("surgeon-reset").IsHiddenAsync());
        await Expect(page.GetByTestId("arm-right"), "MOTORS OFF");
        await page.GetByTestId("surgeon-home").ClickAsync();
        await SurgeonFixture.Until(() => console.Session.Status.RobotState is "PEDAL_UP" or "PEDAL_DOWN", "the robot to come back to PEDAL_UP", 60);
        Assert.Equal(2, asked.Count);
        Assert.StartsWith("Reset:", asked[0], StringComparison.Ordinal);
        Assert.StartsWith("Torque on:", asked[1], StringComparison.Ordinal);
        await page.Context.CloseAsync();
    }

    private async Task<IPage> Open(ConsoleServer server, bool operate)
    {
        if (server.Operator.Holder is { } holder)
        {
            server.Operator.Release(holder);
        }

        var context = await console.Browser.NewContextAsync(new() { ViewportSize = new() { Width = 1920, Height = 1080 } });
        var page = await context.NewPageAsync();
        await page.GotoAsync(ConsoleFixture.PageUrl(server, "surgeon"));
        if (operate)
        {
            await page.Locator("#claim").ClickAsync();
            await Expect(page.Locator("#role"), "operator");
        }

        await page.GetByTestId("hand-right").WaitForAsync(new() { Timeout = 15000 });
        return page;
    }

    private static async Task Expect(ILocator locator, string text, float timeout = 15000)
    {
        try
        {
            await locator.Filter(new() { HasTextString = text }).First.WaitForAsync(new() { Timeout = timeout });
        }
        catch (TimeoutException)
        {
            Assert.Fail($"no {locator} saying \"{text}\"; it says \"{string.Join(" | ", await locator.AllTextContentsAsync())}\"");
        }
    }
}
