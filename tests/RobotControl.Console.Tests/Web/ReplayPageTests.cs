using RobotControl.Host.Session;
using System.Globalization;
using Microsoft.Extensions.Time.Testing;
using Microsoft.Playwright;
using RobotControl.Host.Harness;
using RobotControl.Host.Recording;
using RobotControl.Host.Recording.Mcap;
using RobotControl.WebConsole.Replay;
using RobotControl.WebConsole.Server;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>
/// <c>robotctl console --replay</c> in real headless Chromium: the 3D view shows the joint values the recording holds
/// at the playback time, and the replay bar's slider moves it; the timeline carries the run levels.
/// </summary>
public sealed class ReplayPageTests
{
    [Fact]
    public async Task The_3d_view_shows_the_joint_values_the_recording_holds_at_time_t_and_the_slider_moves_them()
    {
        var file = RecordMainJob();
        var time = new FakeTimeProvider();
        using var replay = new ReplaySession(file, time);
        replay.Play(false);
        replay.Seek(1.2345);
        replay.Pump();
        await using var server = await ConsoleServer.StartAsync(replay, BindAddress.Parse("127.0.0.1:0"), null);
        await using var chromium = await HeadlessChromium.LaunchAsync();
        var page = await (await chromium.Browser.NewContextAsync()).NewPageAsync();
        await page.GotoAsync(ConsoleFixture.PageUrl(server, "view3d"));
        const string Elbow = "robot.right.elbow.position";

        await Assertions.Expect(page.GetByTestId($"joint-{Elbow}")).ToHaveTextAsync(Expected(file, Elbow, 1.2345), new() { Timeout = 30_000 });
        await Assertions.Expect(page.GetByTestId("replay-time")).ToContainTextAsync("1.234 / ", new() { Timeout = 10_000 });
        Assert.True(await page.GetByTestId("replay-timeline").Locator(".mark").CountAsync() >= 3, "the run levels are on the timeline");

        var slider = page.GetByTestId("replay-slider");
        await slider.EvaluateAsync("(s) => { s.value = '0.5'; s.dispatchEvent(new Event('change')); }");
        await Assertions.Expect(page.GetByTestId($"joint-{Elbow}")).ToHaveTextAsync(Expected(file, Elbow, 0.5), new() { Timeout = 30_000 });
        Assert.Equal(0.5, replay.PositionSeconds, 9);
    }

    [Fact]
    public async Task Moving_the_replay_back_starts_the_plot_again_from_the_new_position_instead_of_mixing_two_timelines()
    {
        var file = RecordMainJob();
        var time = new FakeTimeProvider();
        using var replay = new ReplaySession(file, time);
        replay.Seek(1.0);
        await using var server = await ConsoleServer.StartAsync(replay, BindAddress.Parse("127.0.0.1:0"), null);
        await using var chromium = await HeadlessChromium.LaunchAsync();
        var page = await (await chromium.Browser.NewContextAsync(new() { AcceptDownloads = true })).NewPageAsync();
        await page.GotoAsync(ConsoleFixture.PageUrl(server, "plots"));
        await Assertions.Expect(page.GetByTestId("signal-picker").Locator("option").First).ToBeAttachedAsync(new() { Timeout = 30_000 });
        replay.Play(true);
        for (var step = 0; step < 10; step++)
        {
            time.Advance(TimeSpan.FromMilliseconds(50)); // 1.0 s to 1.5 s of the recording
            replay.Pump();
            await page.WaitForTimeoutAsync(100);
        }

        await page.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) > 300", null, new() { Timeout = 30_000 });
        var before = await PlottedTimes(page);
        Assert.True(before[^1] >= 1.45, $"the plot reached {before[^1]} s");

        replay.Seek(0.5);
        replay.Pump();
        await page.WaitForFunctionAsync("() => parseInt(document.querySelector('[data-testid=plot-samples]').textContent) < 50", null, new() { Timeout = 30_000 });
        var after = await PlottedTimes(page);
        Assert.NotEmpty(after);
        Assert.All(after, t => Assert.InRange(t, 0.45, 0.5 + 1e-9));
        Assert.Equal(after.Order(), after);
    }

    /// <summary>Two seconds of the main job recorded (ticks free: the same file on any machine); the file's path.</summary>
    private static string RecordMainJob()
    {
        var file = Path.Combine(Directory.CreateTempSubdirectory("rc-replay-page-").FullName, "main.mcap");
        HeadlessRun.Run(new RunOptions { GraphPath = Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"), Duration = TimeSpan.FromSeconds(2), Record = new RecordingOptions { Path = file }, TickCost = VirtualTickCost.Free }, ConsoleFixture.Catalog());
        return file;
    }

    /// <summary>The plot's rows as its Export CSV gives them: the time column.</summary>
    internal static async Task<IReadOnlyList<double>> PlottedTimes(IPage page)
    {
        var download = await page.RunAndWaitForDownloadAsync(() => page.GetByTestId("export-csv").ClickAsync());
        var lines = await File.ReadAllLinesAsync((await download.PathAsync())!);
        return [.. lines.Skip(1).Where(l => l.Length > 0).Select(l => double.Parse(l.Split(',')[0], CultureInfo.InvariantCulture))];
    }

    /// <summary>The recording's value of <paramref name="signal"/> at the last row at or before <paramref name="t"/>, as the page prints it (6 decimals).</summary>
    private static string Expected(string file, string signal, double t)
    {
        using var recording = McapFile.Open(file);
        var table = CsvExport.Tabulate(recording, RecordingTopics.Signals);
        var row = table.Rows.Last(r => double.Parse(r[0]!, CultureInfo.InvariantCulture) <= t + 1e-12);
        return double.Parse(row[table.Columns.ToList().IndexOf(signal)]!, CultureInfo.InvariantCulture).ToString("F6", CultureInfo.InvariantCulture);
    }
}
