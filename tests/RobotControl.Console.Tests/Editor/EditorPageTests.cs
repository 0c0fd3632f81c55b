using RobotControl.Host.Session;
using System.Text.Json;
using System.Text.Json.Nodes;
using System.Text.RegularExpressions;
using Microsoft.Playwright;
using RobotControl.Host.Harness;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>The graph editor page in real headless Chromium against the console on the virtual robot.</summary>
[Collection(EditorCollection.Name)]
public sealed class EditorPageTests(EditorFixture console)
{
    // The right arm of graphs/teleop-lb.json: instance, type, settings as typed into the settings pane.
    private static readonly (string Name, string Type, (string Setting, string Value)[] Settings)[] Nodes =
    [
        ("touch_right", "touch", [("script", "trajectories/demo-right.csv")]),
        ("homing_right", "homing", [("origin_x_mm", "108.9725"), ("origin_y_mm", "37.0702"), ("origin_z_mm", "-43.785"), ("roll_deg", "90"), ("mirror", "false")]),
        ("scaling_right", "scaling", [("ratio", "0.5"), ("reference_x_mm", "108.9725"), ("reference_y_mm", "37.0702"), ("reference_z_mm", "-43.785")]),
        ("clutch_right", "clutch", []),
        ("ik_right", "inverse_kinematics", [("initial_joints_deg", "-30,-30,0,90,0")]),
        ("walls_right", "haptic_walls", [("roll_deg", "90"), ("mirror", "false")]),
        ("damping_right", "viscous_damping", []),
    ];

    [Fact]
    public async Task The_one_arm_teleop_graph_built_in_the_editor_runs_as_the_hand_written_one()
    {
        var page = await Open();
        await page.GetByTestId("new").ClickAsync();
        foreach (var (name, type, settings) in Nodes)
        {
            await page.Locator($".ged-type[data-type={type}]").ClickAsync();
            await page.GetByTestId("instance-name").FillAsync(name);
            await page.GetByTestId("instance-name").PressAsync("Tab");
            await page.Locator($".drawflow-node[data-instance={name}]").WaitForAsync();
            foreach (var (setting, value) in settings)
            {
                var field = page.Locator($"[data-setting={setting}]");
                if (await field.EvaluateAsync<string>("e => e.tagName") == "SELECT")
                {
                    await field.SelectOptionAsync(value);
                }
                else
                {
                    await field.FillAsync(value);
                    await field.PressAsync("Tab");
                }
            }
        }

        await page.Locator("[data-testid=problems][data-count]").WaitForAsync(); // checked: every node has its ports
        var handWritten = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!;
        foreach (var wire in handWritten["wires"]!.AsArray())
        {
            await Drag(page, (string)wire!["from"]!, (string)wire["to"]!);
        }

        foreach (var wire in handWritten["wires"]!.AsArray().Where(w => (bool?)w!["delayed"] == true))
        {
            var to = (string)wire!["to"]!;
            await page.Locator($".drawflow-node[data-instance={to[..to.IndexOf('.', StringComparison.Ordinal)]}] .gn-head").ClickAsync();
            await page.Locator($"[data-wire='{(string)wire["from"]!}->{to}']").CheckAsync();
        }

        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync(new() { Timeout = 15000 });
        Assert.True(await page.GetByTestId("start").IsEnabledAsync());
        Assert.Equal(3 + 1 + 1, await page.Locator(".connection.delayed").CountAsync()); // forces, force_enable, the clutch's follow
        await page.Locator("#claim").ClickAsync(); // saving is the operator's
        await page.Locator("#role[data-role=operator]").WaitForAsync();
        await page.GetByTestId("file-name").FillAsync("built-in-editor.json");
        await page.GetByTestId("save").ClickAsync();
        await page.Locator("#message.ok").Filter(new() { HasTextString = "saved built-in-editor.json" }).WaitForAsync();
        await Close(page);

        var built = Report("built-in-editor.json");
        var written = Report(EditorFixture.HandWritten);
        Assert.True(built.GetProperty("ticks").GetInt64() == 3000, built.ToString());
        Assert.InRange(built.GetProperty("tracking_error_mm").GetProperty("rms").GetDouble(), 0.001, 2.0);
        Assert.Equal(written.ToString(), built.ToString());
    }

    [Fact]
    public async Task A_node_that_grows_when_its_ports_are_known_pushes_down_the_one_placed_under_it()
    {
        var page = await Open();
        await page.GetByTestId("new").ClickAsync();
        string[] types = ["touch", "homing", "scaling", "clutch", "inverse_kinematics"]; // the fifth goes under the first
        foreach (var type in types)
        {
            await page.Locator($".ged-type[data-type={type}]").ClickAsync();
            await page.Locator($".drawflow-node[data-instance={type}_1]").WaitForAsync();
            await page.Locator("[data-testid=problems][data-count]").WaitForAsync();
        }

        var touch = page.Locator(".drawflow-node[data-instance=touch_1]");
        var ik = page.Locator(".drawflow-node[data-instance=inverse_kinematics_1]");
        var before = (await touch.BoundingBoxAsync())!;
        Assert.Equal(0, await touch.Locator(".output").CountAsync()); // a Touch without its device or script has no ports yet

        await touch.Locator(".gn-head").ClickAsync();
        await page.Locator("[data-setting=script]").FillAsync("trajectories/demo-right.csv");
        await page.Locator("[data-setting=script]").PressAsync("Tab");
        await touch.Locator(".output[data-signal='touch_1.roll']").WaitForAsync();
        await page.Locator("[data-testid=problems][data-count]").WaitForAsync();

        var grown = (await touch.BoundingBoxAsync())!;
        var below = (await ik.BoundingBoxAsync())!;
        Assert.True(grown.Height > before.Height + 100, $"the Touch grew: {before.Height} -> {grown.Height} px");
        Assert.True(below.Y >= grown.Y + grown.Height, $"the IK (top {below.Y}) is below the grown Touch (bottom {grown.Y + grown.Height})");
        await touch.Locator(".output[data-signal='touch_1.roll']").HoverAsync(new() { Trial = true }); // nothing covers its ports
        await Close(page);
    }

    [Fact]
    public async Task Load_add_a_node_wire_it_and_save_changes_the_file_by_that_node_and_wire_alone()
    {
        var page = await Open();
        await page.GetByTestId("graph-list").SelectOptionAsync(EditorFixture.HandWritten);
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("#message").Filter(new() { HasTextString = $"loaded {EditorFixture.HandWritten}" }).WaitForAsync();
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await page.Locator(".ged-type[data-type=viscous_damping]").ClickAsync();
        await page.Locator(".drawflow-node[data-instance=viscous_damping_1]").WaitForAsync();
        await Drag(page, "touch_right.x", "viscous_damping_1.x");
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await page.Locator("#claim").ClickAsync();
        await page.Locator("#role[data-role=operator]").WaitForAsync();
        await page.GetByTestId("file-name").FillAsync("round-trip.json");
        await page.GetByTestId("save").ClickAsync();
        await page.Locator("#message.ok").Filter(new() { HasTextString = "saved round-trip.json" }).WaitForAsync();
        await Close(page);

        var original = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        var saved = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, "round-trip.json")))!.AsObject();
        var added = saved["instances"]!.AsArray().Where(i => !original["instances"]!.AsArray().Any(o => JsonNode.DeepEquals(o, i))).ToList();
        Assert.True(added.Count == 1, string.Join("\n", added.Select(a => a!.ToJsonString())));
        Assert.Equal("""{"name":"viscous_damping_1","type":"viscous_damping","settings":{}}""", added[0]!.ToJsonString()); // every setting at its default
        Assert.Equal(original["instances"]!.AsArray().Count + 1, saved["instances"]!.AsArray().Count);
        var newWires = saved["wires"]!.AsArray().Where(w => !original["wires"]!.AsArray().Any(o => JsonNode.DeepEquals(o, w))).ToList();
        Assert.Equal("""{"from":"touch_right.x","to":"viscous_damping_1.x"}""", Assert.Single(newWires)!.ToJsonString());
        Assert.Equal(original["wires"]!.AsArray().Count + 1, saved["wires"]!.AsArray().Count);
        foreach (var (key, value) in original.Where(p => p.Key is not "instances" and not "wires" and not "layout"))
        {
            Assert.True(JsonNode.DeepEquals(value, saved[key]), $"{key}: {value?.ToJsonString()} became {saved[key]?.ToJsonString()}");
        }

        // The one other field: where the editor drew each node (a file without it is laid out when loaded).
        Assert.Equal(["instances", "layout", "wires"], saved.Select(p => p.Key).Except(original.Select(p => p.Key).Where(k => k is not "instances" and not "wires")).Order());
    }

    [Fact]
    public async Task An_invalid_setting_and_an_invalid_wire_show_their_problem_and_block_start()
    {
        var page = await Open();
        await page.GetByTestId("graph-list").SelectOptionAsync(EditorFixture.HandWritten);
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await EditorFixture.ZoomInUntilLabelsShow(page); // zoomed out, a node shows its name alone

        await page.Locator(".drawflow-node[data-instance=scaling_right] .gn-head").ClickAsync();
        await page.Locator("[data-setting=ratio]").FillAsync("500");
        await page.Locator("[data-setting=ratio]").PressAsync("Tab");
        var onNode = page.Locator(".drawflow-node.gn-bad[data-instance=scaling_right] .gn-problems");
        await onNode.Filter(new() { HasTextRegex = new Regex(Regex.Escape("$.instances[2].settings.ratio: 500 is outside")) }).WaitForAsync();
        Assert.False(await page.GetByTestId("start").IsEnabledAsync());

        await page.Keyboard.PressAsync("Control+z");
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        Assert.True(await page.GetByTestId("start").IsEnabledAsync());

        await page.Locator(".drawflow-node[data-instance=damping_right] .gn-head").ClickAsync();
        await page.Locator("[data-wire='damping_right.fx->touch_right.force_x']").UncheckAsync();
        var onWire = page.Locator(".connection.problem");
        await onWire.First.WaitForAsync();
        Assert.Matches(@"^\$\.wires\[\d+\][^:]*: cycle without a delayed wire", await onWire.First.GetAttributeAsync("data-problem"));
        Assert.False(await page.GetByTestId("start").IsEnabledAsync());

        await page.Keyboard.PressAsync("Control+z");
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await page.Keyboard.PressAsync("Control+Shift+z");
        await page.Locator(".connection.problem").First.WaitForAsync();
        await Close(page);
    }

    [Fact]
    public async Task Started_from_the_editor_the_graph_shows_live_values_that_change_and_stops()
    {
        var page = await Open();
        await page.Locator("#claim").ClickAsync();
        await page.GetByTestId("graph-list").SelectOptionAsync(EditorFixture.HandWritten);
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await EditorFixture.ZoomInUntilLabelsShow(page); // zoomed out, a node shows its name alone
        await page.GetByTestId("start").ClickAsync();
        try
        {
            await page.Locator("[data-testid=run-state][data-running=true]").Filter(new() { HasTextString = EditorFixture.HandWritten }).WaitForAsync(new() { Timeout = 30000 });
        }
        catch (TimeoutException)
        {
            Assert.Fail($"did not start: {await page.Locator("#message").TextContentAsync()} / {await page.GetByTestId("run-state").TextContentAsync()}");
        }


        var live = page.Locator(".gn-port[data-signal='touch_right.x'] .gn-live");
        await live.Filter(new() { HasTextRegex = new Regex("[0-9]") }).WaitForAsync(new() { Timeout = 15000 });
        var first = await live.TextContentAsync();
        await page.WaitForFunctionAsync("v => document.querySelector(\".gn-port[data-signal='touch_right.x'] .gn-live\").textContent !== v", first, new() { Timeout = 15000 });
        var input = page.Locator(".gn-port[data-dir=in][data-signal='homing_right.x'] .gn-live");
        Assert.Matches("[0-9]", await input.TextContentAsync());
        Assert.Equal(EditorFixture.HandWritten, Path.GetFileName(console.Session.Status.Graph));

        await page.GetByTestId("stop").ClickAsync();
        await page.Locator("[data-testid=run-state][data-running=false]").WaitForAsync(new() { Timeout = 30000 });
        Assert.Equal("stopped", console.Session.Status.Session);
        Assert.False(console.Session.Status.TorqueOn);
        Assert.Equal("", await live.TextContentAsync());
        await Close(page);
    }

    [Fact]
    public async Task Screenshot_of_the_teleop_graph()
    {
        if (Path.GetFileName(console.Runner.View.Graph) != "teleop-lb.json")
        {
            Assert.True((await console.Runner.StartAsync(Path.Combine(console.Graphs, "teleop-lb.json"))).Running); // live values in the picture
        }

        var page = await Open(2560, 1440);
        await page.GetByTestId("graph-list").SelectOptionAsync("teleop-lb.json");
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("[data-testid=problems][data-count='0']").WaitForAsync();
        await page.Locator(".drawflow-node[data-instance=scaling_right] .gn-head").ClickAsync();
        Assert.Equal(15, await page.Locator(".drawflow-node").CountAsync());
        if (Environment.GetEnvironmentVariable("CONSOLE_SCREENSHOTS") is { Length: > 0 } dir)
        {
            Directory.CreateDirectory(dir);
            await page.ScreenshotAsync(new() { Path = Path.Combine(dir, "graph-editor.png") });
        }

        Assert.Equal(6 + 2 + 2 + 12, await page.Locator(".connection.delayed").CountAsync()); // forces, force_enable, the clutches' follow, the IKs' follow and measured joints

        await Close(page);
    }

    /// <summary>Drags a wire from output <paramref name="from"/> to input <paramref name="to"/> with the mouse.</summary>
    private static async Task Drag(IPage page, string from, string to)
    {
        var wire = page.Locator($".connection[data-wire='{from} -> {to}']");
        for (var attempt = 1; ; attempt++)
        {
            // Let the check of the last change land first (it may redraw the nodes with their ports).
            await page.Locator("[data-testid=problems][data-count]").WaitForAsync();
            await page.Locator($".output[data-signal='{from}']").DragToAsync(page.Locator($".input[data-signal='{to}']"));
            try
            {
                await wire.WaitForAsync(new() { Timeout = 3000 });
                return;
            }
            catch (TimeoutException) when (attempt < 2)
            {
                // a drop on a node being redrawn is lost, as a hand's would be: drag again
            }
        }
    }

    /// <summary>The report of <c>robotctl run --virtual</c> on a graph of the folder, without its wall-clock timing.</summary>
    private JsonElement Report(string graph)
    {
        var report = HeadlessRun.Run(new RunOptions { GraphPath = Path.Combine(console.Graphs, graph), Duration = TimeSpan.FromSeconds(3), TickCost = VirtualTickCost.Free }, ConsoleFixture.Catalog());
        var json = JsonNode.Parse(report.ToJson())!.AsObject();
        json.Remove("tick_us"); // wall-clock time of each tick: differs from run to run of the same graph
        return JsonSerializer.Deserialize<JsonElement>(json.ToJsonString());
    }

    private Task<IPage> Open(int width = 2560, int height = 1440) => console.OpenEditor(width, height);

    private static Task Close(IPage page) => EditorFixture.CloseEditor(page);
}
