using Microsoft.Playwright;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>The editor never loses work nor destroys it without asking: drafts, the unsaved mark, and its confirmations.</summary>
[Collection(EditorCollection.Name)]
public sealed class EditorDraftTests(EditorFixture console)
{
    [Fact]
    public async Task Unsaved_edits_and_their_undo_steps_survive_a_reload_and_saving_clears_them()
    {
        var page = await console.OpenEditor();
        var asked = new List<string>();
        page.Dialog += (_, dialog) => { asked.Add(dialog.Message); _ = dialog.AcceptAsync(); };
        await EditorFixture.LoadWithoutProblems(page, EditorFixture.HandWritten);
        Assert.True(await page.GetByTestId("unsaved").IsHiddenAsync());

        await page.Locator(".drawflow-node[data-instance=scaling_right] .gn-head").ClickAsync();
        var loaded = await page.Locator("[data-setting=ratio]").InputValueAsync(); // "" once a save has left the default out
        await SetRatio(page, "0.25");
        await page.GetByTestId("unsaved").WaitForAsync();

        await page.ReloadAsync(); // the browser asks first (beforeunload); the handler says leave
        asked.Clear();
        await page.Locator("#message").Filter(new() { HasTextString = $"restored the unsaved edits of {EditorFixture.HandWritten}" }).WaitForAsync();
        await page.GetByTestId("unsaved").WaitForAsync();
        await page.Locator(".drawflow-node[data-instance=scaling_right] .gn-head").ClickAsync();
        Assert.Equal("0.25", await page.Locator("[data-setting=ratio]").InputValueAsync());

        await page.Keyboard.PressAsync("Control+z"); // the undo step came back with the draft
        await page.Locator(".drawflow-node[data-instance=scaling_right] .gn-head").ClickAsync();
        Assert.Equal(loaded, await page.Locator("[data-setting=ratio]").InputValueAsync());
        await page.GetByTestId("unsaved").WaitForAsync(new() { State = WaitForSelectorState.Hidden }); // back to the file as loaded

        await page.Keyboard.PressAsync("Control+Shift+z");
        await page.GetByTestId("unsaved").WaitForAsync();
        await page.Locator("#claim").ClickAsync();
        await page.Locator("#role[data-role=operator]").WaitForAsync();
        await page.GetByTestId("file-name").FillAsync("drafted.json");
        await page.GetByTestId("save").ClickAsync();
        await page.Locator("#message.ok").Filter(new() { HasTextString = "saved drafted.json" }).WaitForAsync();
        Assert.True(await page.GetByTestId("unsaved").IsHiddenAsync());
        Assert.Empty(asked); // a new name: nothing to overwrite
        Assert.Null(await page.EvaluateAsync<string?>("() => localStorage.getItem('rc-editor-draft')"));
        Assert.Contains("\"ratio\": 0.25", File.ReadAllText(Path.Combine(console.Graphs, "drafted.json")), StringComparison.Ordinal);
        await EditorFixture.CloseEditor(page);
    }

    [Fact]
    public async Task Deleting_a_wired_node_overwriting_another_file_and_loading_over_edits_ask_first()
    {
        var page = await console.OpenEditor();
        var asked = new List<string>();
        var answer = false;
        page.Dialog += (_, dialog) =>
        {
            asked.Add(dialog.Message);
            _ = answer ? dialog.AcceptAsync() : dialog.DismissAsync();
        };
        await EditorFixture.LoadWithoutProblems(page, EditorFixture.HandWritten);
        var scaling = page.Locator(".drawflow-node[data-instance=scaling_right]");

        await scaling.Locator(".gn-head").ClickAsync();
        await page.Keyboard.PressAsync("Delete");
        Assert.Equal("Delete node scaling_right and its 7 wires?", Assert.Single(asked));
        Assert.Equal(1, await scaling.CountAsync()); // said no: still there, nothing changed
        Assert.True(await page.GetByTestId("unsaved").IsHiddenAsync());

        answer = true;
        await page.GetByTestId("delete-node").ClickAsync();
        await scaling.WaitForAsync(new() { State = WaitForSelectorState.Detached });
        Assert.Equal(2, asked.Count);
        await page.GetByTestId("unsaved").WaitForAsync();

        answer = false;
        var before = File.ReadAllText(Path.Combine(console.Graphs, "teleop-lb.json"));
        await page.Locator("#claim").ClickAsync();
        await page.Locator("#role[data-role=operator]").WaitForAsync();
        await page.GetByTestId("file-name").FillAsync("teleop-lb.json");
        await page.GetByTestId("save").ClickAsync();
        Assert.Equal("teleop-lb.json exists: overwrite it?", asked[2]);
        Assert.Equal(before, File.ReadAllText(Path.Combine(console.Graphs, "teleop-lb.json")));

        await page.GetByTestId("graph-list").SelectOptionAsync("teleop-lb.json");
        await page.GetByTestId("load").ClickAsync();
        Assert.StartsWith("Discard the unsaved edits of teleop-lb.json?", asked[3], StringComparison.Ordinal);
        Assert.Equal(0, await scaling.CountAsync()); // kept the edits
        await page.GetByTestId("unsaved").WaitForAsync();
        await page.EvaluateAsync("() => localStorage.removeItem('rc-editor-draft')");
        await EditorFixture.CloseEditor(page);
    }

    private static async Task SetRatio(IPage page, string value)
    {
        await page.Locator("[data-setting=ratio]").FillAsync(value);
        await page.Locator("[data-setting=ratio]").PressAsync("Tab");
    }
}
