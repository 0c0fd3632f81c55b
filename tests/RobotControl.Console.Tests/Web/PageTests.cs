using System.Globalization;
using System.Text.RegularExpressions;
using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>The pages in real headless Chromium against the console on the virtual robot.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class PageTests(ConsoleFixture console)
{
    private const string Elbow = "right.elbow";

    [Fact]
    public async Task Discover_lists_the_six_modules()
    {
        var page = await Open("bus", operate: true);
        await page.GetByTestId("discover").ClickAsync();
        await Expect(page, "#message.error", "discovery needs the motors off, the run level is PEDAL_UP: turn torque off first");
        await Click(page, "torque-off", "motors off (run level INIT)");
        await page.GetByTestId("discover").ClickAsync();
        await Expect(page, "#message.ok", "6 of 6 modules found");
        Assert.Equal(6, await page.Locator("[data-controller]").CountAsync());
        Assert.Equal(6, await page.Locator("[data-field=present]", new() { HasTextString = "present" }).CountAsync());
        await Click(page, "torque-on", "motors on, holding (run level PEDAL_UP)");
        await Close(page);
    }

    [Fact]
    public async Task Jog_moves_the_joint_and_the_virtual_robot_agrees()
    {
        var page = await Open("bus", operate: true);
        var readout = page.GetByTestId($"position-{Elbow}");
        var before = await Number(readout);
        await page.GetByLabel($"jog speed of {Elbow}").FillAsync("20");
        await page.GetByTestId($"jog-plus-{Elbow}").ClickAsync();
        await Expect(page, "#message.error", "jog moves the robot: it needs the run level PEDAL_DOWN, it is PEDAL_UP (press the pedal)");
        await Click(page, "pedal-down", "run level PEDAL_DOWN");
        await page.GetByTestId($"jog-plus-{Elbow}").ClickAsync();
        await Expect(page, "#message.ok", "jogging at 20 deg/s");
        await page.WaitForTimeoutAsync(1500);
        await page.GetByTestId($"jog-stop-{Elbow}").ClickAsync();
        await Expect(page, "#message.ok", "jog stopped");
        await page.WaitForTimeoutAsync(800);
        var after = await Number(readout);
        Assert.True(after - before > 5, $"the readout moved from {before} to {after}");
        var truth = await console.Session.VirtualOutputDeg(Elbow);
        Assert.True(Math.Abs(truth - after) < 1.0, $"page {after} deg, virtual robot {truth} deg");
        await Screenshot(page, "bus.png");
        string? asked = null;
        page.Dialog += (_, dialog) =>
        {
            asked = dialog.Message;
            _ = dialog.AcceptAsync();
        };
        await page.GetByRole(AriaRole.Row).Filter(new() { Has = page.GetByTestId($"position-{Elbow}") }).GetByRole(AriaRole.Button, new() { Name = "Release" }).ClickAsync();
        await Expect(page, "#message.ok", "back under the control loop");
        Assert.StartsWith($"Release {Elbow}: it will move ", asked, StringComparison.Ordinal); // the jog took it further than the warning's 2 deg from the graph's command
        await Click(page, "pedal-up", "run level PEDAL_UP");
        await Close(page);
    }

    [Fact]
    public async Task A_gain_written_on_the_page_survives_a_module_reboot()
    {
        var page = await Open("bus", operate: true);
        page.Dialog += (_, dialog) => dialog.AcceptAsync();
        await Click(page, "torque-off", "motors off");
        var input = page.GetByLabel($"P gain of {Elbow}");
        await input.FillAsync("12.5");
        await page.GetByTestId($"write-kp-{Elbow}").ClickAsync();
        await Expect(page, "#message.ok", "written to FRAM");
        var id = await page.Locator("[data-controller]").Filter(new() { Has = page.GetByTestId($"position-{Elbow}") }).GetAttributeAsync("data-controller");
        await page.GetByTestId($"reboot-{id}").ClickAsync();
        await Expect(page, "#message.ok", "rebooted");
        await page.WaitForTimeoutAsync(500);
        await page.Locator($"[data-controller=\"{id}\"]").GetByRole(AriaRole.Button, new() { Name = "Re-read parameters" }).ClickAsync();
        await Expect(page, "#message.ok", "parameters read");
        await page.ReloadAsync();
        await page.WaitForSelectorAsync($"[data-testid=\"position-{Elbow}\"]");
        await page.WaitForTimeoutAsync(600);
        var value = double.Parse(await page.GetByLabel($"P gain of {Elbow}").InputValueAsync(), CultureInfo.InvariantCulture);
        Assert.InRange(value, 12.45, 12.55);
        using var http = console.Client("reader");
        var events = await http.GetStringAsync("api/events");
        Assert.Contains($"module {id}", events, StringComparison.Ordinal);
        Assert.Contains("reset (software)", events, StringComparison.Ordinal);
        await Click(page, "torque-on", "motors on");
        await Close(page);
    }

    [Fact]
    public async Task A_refused_write_shows_the_module_error()
    {
        var page = await Open("bus", operate: true);
        page.Dialog += (_, dialog) => dialog.AcceptAsync();
        var before = await page.GetByLabel($"current limit of {Elbow}").InputValueAsync();
        var gain = await page.GetByLabel($"P gain of {Elbow}").InputValueAsync();

        // Motors on: the module refuses a persistent write itself (access error), and the page says what to do.
        await page.GetByLabel($"P gain of {Elbow}").FillAsync("9");
        await page.GetByTestId($"write-kp-{Elbow}").ClickAsync();
        await Expect(page, "#message.error", "module 2: writing kp[0] = 401 failed (Ok, 0x07 access error): the persistent area is locked while torque is on, turn torque off first");
        await Click(page, "torque-off", "motors off");

        // Motors off: 0.3 A is 4914 ADC counts on the 0.25 A-full-scale arm module, outside current_limit's range
        // (0..4095): the page offers the range the parameter path accepts, in amperes, and sends nothing.
        var limit = page.GetByLabel($"current limit of {Elbow}");
        await limit.FillAsync("0.3");
        await page.GetByTestId($"write-current_limit-{Elbow}").ClickAsync();
        Assert.Equal("give 0.000..0.250 A", await limit.EvaluateAsync<string>("e => e.validationMessage"));
        await page.ReloadAsync();
        await page.WaitForSelectorAsync($"[data-testid=\"position-{Elbow}\"]");
        await page.WaitForTimeoutAsync(600);
        Assert.Equal(before, await page.GetByLabel($"current limit of {Elbow}").InputValueAsync());
        Assert.Equal(gain, await page.GetByLabel($"P gain of {Elbow}").InputValueAsync());
        await Click(page, "torque-on", "motors on");
        await Close(page);
    }

    [Fact]
    public async Task A_plot_receives_data()
    {
        var page = await Open("plots", operate: false);
        await page.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 100", null, new() { Timeout = 15000 });
        Assert.True(await page.Locator(".plot canvas").CountAsync() > 0);

        // Two signals in one plot while another console jogs the elbow out and back.
        await page.GetByTestId("signal-picker").SelectOptionAsync([$"robot.{Elbow}.position", $"robot.{Elbow}.command"]);
        using var http = await console.Operator("operator-plots");
        await Post(http, "api/pedal", "{\"down\": true}");
        foreach (var speed in new[] { 40, -40, 0 })
        {
            await Post(http, $"api/motors/{Elbow}/jog", $"{{\"degPerS\": {speed}}}");
            await page.WaitForTimeoutAsync(1200);
        }

        await Post(http, $"api/motors/{Elbow}/release", "{}");
        await Post(http, "api/pedal", "{\"down\": false}");
        await page.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 2000", null, new() { Timeout = 15000 });
        await Screenshot(page, "plots.png");
        console.ReleaseOperator();
        await Close(page);
    }

    [Fact]
    public async Task The_3D_view_renders_and_moves_with_a_joint()
    {
        var page = await Open("view3d", operate: false);
        await page.WaitForTimeoutAsync(2500);
        var first = await Pixels(page);
        Assert.True(first.Drawn > 500, $"only {first.Drawn} pixels differ from the background");
        using var http = await console.Operator("operator-3d");
        (await http.PostAsync("api/pedal", new StringContent("{\"down\": true}", System.Text.Encoding.UTF8, "application/json"))).EnsureSuccessStatusCode();
        (await http.PostAsync("api/motors/right.shoulder_yaw/jog", new StringContent("{\"degPerS\": 60}", System.Text.Encoding.UTF8, "application/json"))).EnsureSuccessStatusCode();
        await page.WaitForTimeoutAsync(1500);
        (await http.PostAsync("api/motors/right.shoulder_yaw/jog", new StringContent("{\"degPerS\": 0}", System.Text.Encoding.UTF8, "application/json"))).EnsureSuccessStatusCode();
        await page.WaitForTimeoutAsync(500);
        var second = await Pixels(page);
        var changed = first.Signature.Zip(second.Signature).Count(p => p.First != p.Second);
        Assert.True(changed > 20, $"only {changed} sampled pixels changed after the joint moved");
        await Screenshot(page, "view3d.png");
        (await http.PostAsync("api/motors/right.shoulder_yaw/release", null)).EnsureSuccessStatusCode();
        (await http.PostAsync("api/pedal", new StringContent("{\"down\": false}", System.Text.Encoding.UTF8, "application/json"))).EnsureSuccessStatusCode();
        console.ReleaseOperator();
        await Close(page);
    }

    [Fact]
    public async Task The_run_status_page_shows_the_loop_and_the_event_log()
    {
        var page = await Open("status", operate: false);
        await Expect(page, "[data-testid=run-status]", "1000 Hz");
        await Expect(page, "[data-testid=event-log]", "found");
        await Screenshot(page, "status.png");
        await Close(page);
    }

    [Fact]
    public async Task The_record_button_records_the_session_to_a_file_the_official_reader_reads()
    {
        var page = await Open("status", operate: true);
        await Expect(page, "[data-testid=recording-file]", "not recording");
        await page.GetByTestId("record").ClickAsync();
        await Expect(page, "#message.ok", $"recording to {ConsoleFixture.RecordFolder}");
        await Expect(page, "[data-testid=recording-file]", "recording to ");
        var file = console.Session.RecordingFile!;
        await page.WaitForTimeoutAsync(1000); // a second of the session recorded
        await page.GetByTestId("record").ClickAsync();
        await Expect(page, "#message.ok", $"recording: {file}: ");
        await Expect(page, "[data-testid=recording-file]", "not recording");
        var check = RobotControl.TestSupport.Mcap.McapCheck.Read(file);
        Assert.Null(check.Error);
        Assert.True(check.Complete);
        Assert.True(check.IndexedCounts["/arms/right/joints"] > 100, $"{check.IndexedCounts["/arms/right/joints"]} joint messages");
        Assert.Contains($"{check.IndexedCounts.Values.Sum()} messages", await page.Locator("#message").InnerTextAsync(), StringComparison.Ordinal);
        await Close(page);
    }

    private Task<IPage> Open(string hash, bool operate) => console.OpenPage(hash, operate);

    private Task Close(IPage page) => console.ClosePage(page);

    private static async Task Post(HttpClient http, string path, string json) =>
        (await http.PostAsync(path, new StringContent(json, System.Text.Encoding.UTF8, "application/json"))).EnsureSuccessStatusCode();

    /// <summary>Clicks a toolbar button and waits for the success message that contains <paramref name="text"/>.</summary>
    internal static async Task Click(IPage page, string testId, string text)
    {
        await page.GetByTestId(testId).ClickAsync();
        await Expect(page, "#message.ok", text);
    }

    /// <summary>Waits up to 15 s for an element matching <paramref name="selector"/> whose text contains <paramref name="text"/>; fails with the message line.</summary>
    internal static async Task Expect(IPage page, string selector, string text)
    {
        try
        {
            await page.Locator(selector).Filter(new() { HasTextRegex = new Regex(Regex.Escape(text)) }).First.WaitForAsync(new() { Timeout = 15000 });
        }
        catch (TimeoutException)
        {
            Assert.Fail($"no {selector} saying \"{text}\"; the message line says \"{await page.Locator("#message").TextContentAsync()}\"");
        }
    }

    private static async Task<double> Number(ILocator locator)
    {
        await locator.Filter(new() { HasTextRegex = new Regex("[0-9]") }).WaitForAsync();
        return double.Parse(await locator.TextContentAsync() ?? "nan", CultureInfo.InvariantCulture);
    }

    private static async Task<(int Drawn, int[] Signature)> Pixels(IPage page)
    {
        var result = await page.EvaluateAsync<int[]>(@"() => {
            const c = document.querySelector('canvas[data-testid=view3d]');
            const t = document.createElement('canvas'); t.width = c.width; t.height = c.height;
            const g = t.getContext('2d'); g.drawImage(c, 0, 0);
            const d = g.getImageData(0, 0, t.width, t.height).data;
            const bg = [d[0], d[1], d[2]];
            let drawn = 0; const sig = [];
            for (let i = 0; i < d.length; i += 4) {
                const diff = Math.abs(d[i] - bg[0]) + Math.abs(d[i + 1] - bg[1]) + Math.abs(d[i + 2] - bg[2]);
                if (diff > 30) drawn++;
                if ((i / 4) % 97 === 0) sig.push(diff > 30 ? 1 : 0);
            }
            return [drawn, ...sig];
        }");
        return (result[0], result[1..]);
    }

    internal static async Task Screenshot(IPage page, string name)
    {
        if (Environment.GetEnvironmentVariable("CONSOLE_SCREENSHOTS") is { Length: > 0 } dir)
        {
            Directory.CreateDirectory(dir);
            await page.ScreenshotAsync(new() { Path = Path.Combine(dir, name) });
        }
    }
}
