using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests.Web;

/// <summary>The 3D view's own controls in real headless Chromium: it fills the window, names each arm, and its view resets.</summary>
[Collection(ConsoleCollection.Name)]
public sealed class View3dPageTests(ConsoleFixture console)
{
    [Fact]
    public async Task The_view_fills_the_window_labels_each_arm_and_goes_back_to_its_framing_after_an_orbit()
    {
        var page = await console.OpenPage("view3d", operate: false);
        var canvas = page.GetByTestId("view3d");
        await page.GetByTestId("arm-label-left").WaitForAsync();
        Assert.Equal("right arm", await page.GetByTestId("arm-label-right").TextContentAsync());
        Assert.Equal("left arm", await page.GetByTestId("arm-label-left").TextContentAsync());

        var box = (await canvas.BoundingBoxAsync())!;
        var viewport = page.ViewportSize!;
        Assert.True(box.Width > 0.9 * viewport.Width - 60, $"{box.Width} px wide in a {viewport.Width} px window");
        Assert.True(box.Height > 0.6 * viewport.Height, $"{box.Height} px high in a {viewport.Height} px window");
        Assert.InRange(await canvas.EvaluateAsync<int>("c => c.width"), box.Width - 2, box.Width + 2); // drawn at its size, not stretched

        var framed = await canvas.GetAttributeAsync("data-camera");
        Assert.False(string.IsNullOrEmpty(framed));
        await page.Mouse.MoveAsync(box.X + (box.Width / 2), box.Y + (box.Height / 2));
        await page.Mouse.DownAsync();
        await page.Mouse.MoveAsync(box.X + (box.Width / 2) + 200, box.Y + (box.Height / 2) + 60, new() { Steps = 10 });
        await page.Mouse.UpAsync();
        await page.WaitForFunctionAsync("v => document.querySelector('canvas[data-testid=view3d]').dataset.camera !== v", framed);

        await page.GetByTestId("reset-view").ClickAsync();
        await page.WaitForFunctionAsync("v => document.querySelector('canvas[data-testid=view3d]').dataset.camera === v", framed);
        await console.ClosePage(page);
    }
}
