using System.Globalization;
using System.Text.Json;
using System.Text.RegularExpressions;
using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>
/// The tuning page (one motor: desired and measured plot, jog, gains, release) and the angles in degrees on the plots
/// page, in real headless Chromium against the console on the virtual robot.
/// </summary>
[Collection(ConsoleCollection.Name)]
public sealed partial class TuningPageTests(ConsoleFixture console)
{
    private const string Elbow = "right.elbow";

    [Fact]
    public async Task A_jog_moves_the_joint_and_the_plotted_desired_follows_the_jog_target_the_server_sends()
    {
        var page = await OpenElbow();
        using var http = console.Client("reader-tune");
        var start = await PedalDown(page, http);
        var desiredBefore = await Plotted(page, "desired");
        var up = start.GetProperty("maxDeg").GetDouble() - start.GetProperty("positionDeg").GetDouble() > 40;

        await page.GetByLabel($"jog speed of {Elbow}").FillAsync("20");
        await page.GetByTestId(up ? $"jog-plus-{Elbow}" : $"jog-minus-{Elbow}").ClickAsync();
        await PageTests.Expect(page, "#message.ok", $"jogging at {(up ? "20" : "-20")} deg/s");
        await page.WaitForTimeoutAsync(1500);
        await PageTests.Click(page, $"jog-stop-{Elbow}", "jog stopped");
        await page.WaitForTimeoutAsync(1000);

        var desired = await Plotted(page, "desired");
        var measured = await Plotted(page, "measured");
        var now = await ConsoleFixture.Motor(http, Elbow);
        var moved = (desired - desiredBefore) * (up ? 1 : -1);
        Assert.True(moved > 10, $"the plotted desired went from {desiredBefore:F2} to {desired:F2} deg");
        Assert.True(Math.Abs(desired - now.GetProperty("desiredDeg").GetDouble()) < 0.5, $"plotted desired {desired:F2} deg, the server's {now.GetProperty("desiredDeg").GetDouble():F2} deg");
        Assert.True(Math.Abs(measured - desired) < 2, $"measured {measured:F2} deg did not follow desired {desired:F2} deg");
        Assert.True(now.GetProperty("manual").GetBoolean()); // the desired is the jog's target, held since the stop
        await PageTests.Screenshot(page, "tune.png");

        await console.Session.ReleaseAsync(Elbow);
        await PageTests.Click(page, "pedal-up", "run level PEDAL_UP");
        await console.ClosePage(page);
    }

    [Fact]
    public async Task A_release_far_from_the_graphs_command_asks_first_and_a_no_leaves_the_motor_in_manual()
    {
        var page = await OpenElbow();
        using var http = console.Client("reader-release");
        var start = await PedalDown(page, http);
        var command = start.GetProperty("loopCommandDeg").GetDouble();
        var target = command + (start.GetProperty("maxDeg").GetDouble() - command > 45 ? 35 : -35);
        await page.GetByLabel($"setpoint of {Elbow}").FillAsync(target.ToString("F1", CultureInfo.InvariantCulture));
        await PageTests.Click(page, $"go-{Elbow}", "moving to");
        await Until(async () => Math.Abs((await ConsoleFixture.Motor(http, Elbow)).GetProperty("positionDeg").GetDouble() - target) < 1);

        var answers = new Queue<bool>([false, true]);
        var asked = new List<string>();
        page.Dialog += (_, dialog) =>
        {
            asked.Add(dialog.Message);
            _ = answers.Dequeue() ? dialog.AcceptAsync() : dialog.DismissAsync();
        };
        // The graph's command moves (the Touch plays a demo trajectory): the question's distance is the server's at the
        // click, between what the server said just before and just after it.
        var before = Distance(await ConsoleFixture.Motor(http, Elbow));
        await PageTests.Click(page, $"release-{Elbow}", "cancelled: it stays in manual");
        var after = Distance(await ConsoleFixture.Motor(http, Elbow));
        var question = Question().Match(Assert.Single(asked));
        Assert.True(question.Success, asked[0]);
        var speed = start.GetProperty("speedLimitDegS").GetDouble();
        var move = double.Parse(question.Groups["deg"].Value, CultureInfo.InvariantCulture);
        Assert.InRange(move, Math.Min(before, after) - 0.5, Math.Max(before, after) + 0.5);
        Assert.True(move > 2, $"asked for a {move} deg move");
        Assert.InRange(double.Parse(question.Groups["s"].Value, CultureInfo.InvariantCulture), (move / speed) - 0.06, (move / speed) + 0.06);
        await page.WaitForTimeoutAsync(300);
        var stayed = await ConsoleFixture.Motor(http, Elbow);
        Assert.True(stayed.GetProperty("manual").GetBoolean(), "a release answered no released the motor");
        Assert.True(Math.Abs(stayed.GetProperty("positionDeg").GetDouble() - target) < 1);

        await PageTests.Click(page, $"release-{Elbow}", "back under the control loop");
        Assert.Equal(2, asked.Count);
        Assert.False((await ConsoleFixture.Motor(http, Elbow)).GetProperty("manual").GetBoolean());
        await Until(async () => Distance(await ConsoleFixture.Motor(http, Elbow)) < 2);
        await PageTests.Click(page, "pedal-up", "run level PEDAL_UP");
        await console.ClosePage(page);
    }

    [Fact]
    public async Task The_plots_page_shows_an_angle_in_degrees_the_servers_radians_times_180_over_pi_and_in_radians_when_asked()
    {
        var page = await console.OpenPage("plots", operate: false);
        var signal = $"robot.{Elbow}.position";
        await page.GetByTestId("signal-picker").SelectOptionAsync([signal]);
        await page.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 100", null, new() { Timeout = 15000 });

        var (header, time, value) = await LastCsvRow(page);
        Assert.Equal($"time_s,{signal} (deg)", header);
        var rad = RingValue(signal, time);
        Assert.Equal(rad * 180 / Math.PI, value, 9);
        Assert.True(Math.Abs(value - rad) > 1e-3, $"{value} is the radians {rad}"); // an elbow at 0 would not tell them apart

        await page.GetByTestId("angle-unit").SelectOptionAsync("rad");
        (header, time, value) = await LastCsvRow(page);
        Assert.Equal($"time_s,{signal} (rad)", header);
        Assert.Equal(RingValue(signal, time), value, 12);
        await console.ClosePage(page);
    }

    [GeneratedRegex(@"^Release right\.elbow: it will move (?<deg>[0-9]+\.[0-9])° back to the graph's command in about (?<s>[0-9]+\.[0-9]) s\. Release\?$")]
    private static partial Regex Question();

    private async Task<IPage> OpenElbow()
    {
        var page = await console.OpenPage("tune", operate: true);
        await page.GetByTestId("tune-motor").SelectOptionAsync(Elbow);
        await page.GetByTestId($"jog-plus-{Elbow}").WaitForAsync();
        return page;
    }

    /// <summary>How far a release would move the motor: its measured position from the graph's command, degrees.</summary>
    private static double Distance(JsonElement motor) =>
        Math.Abs(motor.GetProperty("loopCommandDeg").GetDouble() - motor.GetProperty("positionDeg").GetDouble());

    /// <summary>
    /// Presses the pedal on the page and returns the elbow's view once the graph drives it: at PEDAL_DOWN the graph's
    /// command takes over from the goals held since the motors went on (the elbow moves to it).
    /// </summary>
    private static async Task<JsonElement> PedalDown(IPage page, HttpClient http)
    {
        await PageTests.Click(page, "pedal-down", "run level PEDAL_DOWN");
        await Until(async () =>
        {
            var m = await ConsoleFixture.Motor(http, Elbow);
            return !m.GetProperty("manual").GetBoolean() && Math.Abs(m.GetProperty("desiredDeg").GetDouble() - m.GetProperty("loopCommandDeg").GetDouble()) < 0.5;
        });
        await page.WaitForTimeoutAsync(500); // the plot has drawn the settled elbow
        return await ConsoleFixture.Motor(http, Elbow);
    }

    /// <summary>The last value the tuning plot drew of a trace (its test hook), once it has drawn one.</summary>
    private static async Task<double> Plotted(IPage page, string trace)
    {
        var attribute = $"data-{trace}-deg";
        await page.WaitForFunctionAsync($"() => (document.querySelector('[data-testid=tune-plot]').getAttribute('{attribute}') ?? '') !== ''", null, new() { Timeout = 15000 });
        return double.Parse(await page.GetByTestId("tune-plot").GetAttributeAsync(attribute) ?? "nan", CultureInfo.InvariantCulture);
    }

    /// <summary>The plots page's CSV export: its header and its last row (one signal).</summary>
    private static async Task<(string Header, double Time, double Value)> LastCsvRow(IPage page)
    {
        var download = await page.RunAndWaitForDownloadAsync(() => page.GetByTestId("export-csv").ClickAsync());
        var lines = (await File.ReadAllLinesAsync(await download.PathAsync())).Where(l => l.Length > 0).ToList();
        var last = lines[^1].Split(',');
        return (lines[0], double.Parse(last[0], CultureInfo.InvariantCulture), double.Parse(last[1], CultureInfo.InvariantCulture));
    }

    /// <summary>The session ring's value of <paramref name="signal"/> in its row at <paramref name="time"/> (the server's radians).</summary>
    private double RingValue(string signal, double time)
    {
        var ring = console.Session.Signals;
        var slice = ring.Read(0, [ring.IndexOf(signal)], ring.Capacity);
        var row = slice.Times.ToList().IndexOf(time);
        Assert.True(row >= 0, $"no ring row at {time} s");
        return slice.Values[0][row];
    }

    /// <summary>Waits up to 15 s for <paramref name="condition"/>.</summary>
    private static async Task Until(Func<Task<bool>> condition)
    {
        for (var i = 0; i < 150 && !await condition(); i++)
        {
            await Task.Delay(100);
        }

        Assert.True(await condition(), "not reached within 15 s");
    }
}
