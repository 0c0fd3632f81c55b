using System.Text.Json;
using System.Text.Json.Nodes;
using Microsoft.Playwright;
using Xunit.Abstractions;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>
/// The editor's canvas in real headless Chromium (issue 30): labels readable at the zoom that fits a whole graph,
/// a wire picked where it crosses a node, every problem of a graph listed at once.
/// </summary>
[Collection(EditorCollection.Name)]
public sealed class EditorCanvasTests(EditorFixture console, ITestOutputHelper output)
{
    /// <summary>The smallest text the walk-through could read on screen (px).</summary>
    private const double ReadablePx = 11;

    [Fact]
    public async Task At_the_zoom_that_fits_the_two_arm_graph_and_zoomed_in_from_there_every_drawn_label_is_readable()
    {
        var page = await console.OpenEditor(1280, 800);
        await EditorFixture.LoadWithoutProblems(page, "teleop-lb.json");
        await page.GetByRole(AriaRole.Button, new() { Name = "Fit", Exact = true }).ClickAsync();

        var fitted = await Labels(page, "fitted in 1280x800");
        Assert.True(fitted.Zoom < 1, "the graph needs zooming out to fit");
        Assert.Equal(15, fitted.Names.Length);
        foreach (var node in fitted.Names)
        {
            Assert.Contains(fitted.Drawn, l => l.Node == node && l.Text == node); // each node's name is drawn, readable
        }

        // Zoomed in with the wheel step by step until the port labels show: readable at every step.
        for (var step = 0; !(await Labels(page, $"zoomed in {step}")).Drawn.Any(l => l.Text == "force_x"); step++)
        {
            Assert.True(step < 12, "the port labels show before zoom 1.5");
            await EditorFixture.ZoomInOneStep(page);
        }

        await EditorFixture.CloseEditor(page);
    }

    /// <summary>The text drawn on the canvas's nodes with its size on screen; fails when any is smaller than <see cref="ReadablePx"/> or nodes overlap.</summary>
    private async Task<(double Zoom, string[] Names, List<(string Node, string Text, double Px)> Drawn)> Labels(IPage page, string when)
    {
        var seen = await page.EvaluateAsync<JsonElement>("""
            () => {
              const canvas = document.querySelector('[data-testid=graph-canvas]');
              const labels = [];
              for (const node of canvas.querySelectorAll('.drawflow-node')) {
                const scale = node.getBoundingClientRect().width / node.offsetWidth;
                for (const e of node.querySelectorAll('*')) {
                  const text = [...e.childNodes].filter((n) => n.nodeType === Node.TEXT_NODE).map((n) => n.textContent).join('').trim();
                  if (text === '' || !e.checkVisibility({ visibilityProperty: true, opacityProperty: true })) continue;
                  labels.push({ node: node.dataset.instance, text, px: parseFloat(getComputedStyle(e).fontSize) * scale });
                }
              }
              const first = canvas.querySelector('.drawflow-node');
              const boxes = [...canvas.querySelectorAll('.drawflow-node')].map((n) => ({ name: n.dataset.instance, r: n.getBoundingClientRect() }));
              const overlaps = boxes.flatMap((a, i) => boxes.slice(i + 1).filter((b) => a.r.left < b.r.right && b.r.left < a.r.right && a.r.top < b.r.bottom && b.r.top < a.r.bottom)
                .map((b) => `${a.name} and ${b.name}`));
              return { zoom: first.getBoundingClientRect().width / first.offsetWidth, compact: canvas.classList.contains('compact'), overlaps,
                names: [...canvas.querySelectorAll('.drawflow-node')].map((n) => n.dataset.instance), labels };
            }
            """);
        var drawn = seen.GetProperty("labels").EnumerateArray()
            .Select(l => (Node: l.GetProperty("node").GetString()!, Text: l.GetProperty("text").GetString()!, Px: l.GetProperty("px").GetDouble())).ToList();
        var zoom = seen.GetProperty("zoom").GetDouble();
        output.WriteLine($"teleop-lb {when}: zoom {zoom:0.###}, compact {seen.GetProperty("compact").GetBoolean()}, {drawn.Count} labels drawn, smallest {drawn.Min(l => l.Px):0.#} px on screen");
        var small = drawn.Where(l => l.Px < ReadablePx).ToList();
        Assert.True(small.Count == 0, $"{when}, zoom {zoom:0.###}:\n" + string.Join("\n", small.Select(l => $"{l.Node}: '{l.Text}' {l.Px:0.#} px")));
        Assert.True(seen.GetProperty("overlaps").GetArrayLength() == 0, $"{when}: nodes overlap: {seen.GetProperty("overlaps")}"); // labels grown or hidden, the nodes keep apart
        return (zoom, [.. seen.GetProperty("names").EnumerateArray().Select(n => n.GetString()!)], drawn);
    }

    [Fact]
    public async Task A_click_on_a_wire_where_it_crosses_a_node_picks_the_wire_and_Delete_removes_that_wire_alone()
    {
        // Three nodes of the one-arm graph: touch_right and homing_right side by side, wired, and walls_right between
        // them and lower, so that the lowest of the wires between the first two run straight across the top of its body.
        var arm = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        string[] kept = ["touch_right", "homing_right", "walls_right"];
        var graph = new JsonObject
        {
            ["schema"] = "robotcontrol/graph/1",
            ["instances"] = new JsonArray([.. arm["instances"]!.AsArray().Where(i => kept.Contains((string?)i!["name"])).Select(i => i!.DeepClone())]),
            ["wires"] = new JsonArray([.. arm["wires"]!.AsArray().Where(w => ((string)w!["from"]!).StartsWith("touch_right.", StringComparison.Ordinal)
                && ((string)w["to"]!).StartsWith("homing_right.", StringComparison.Ordinal)).Select(w => w!.DeepClone())]),
            ["layout"] = JsonNode.Parse("""{ "touch_right": { "x": 40, "y": 40 }, "homing_right": { "x": 900, "y": 40 }, "walls_right": { "x": 470, "y": 122 } }"""),
        };
        File.WriteAllText(Path.Combine(console.Graphs, "crossing.json"), graph.ToJsonString());
        var page = await console.OpenEditor();
        await EditorFixture.LoadWithoutProblems(page, "crossing.json");
        var wires = await page.Locator(".connection").CountAsync();

        // A wire of other nodes with a point inside walls_right's body, clear of its edges and of the other wires, and
        // a point of the body clear of every wire.
        var points = await page.EvaluateAsync<JsonElement>("""
            () => {
              const body = document.querySelector('.drawflow-node[data-instance=walls_right] .gn-body').getBoundingClientRect();
              const onScreen = (path) => {
                const m = path.getScreenCTM();
                const n = Math.ceil(path.getTotalLength() / 2);
                return Array.from({ length: n + 1 }, (_, i) => new DOMPoint(path.getPointAtLength(2 * i).x, path.getPointAtLength(2 * i).y).matrixTransform(m));
              };
              const inside = (p, margin) => p.x > body.left + margin && p.x < body.right - margin && p.y > body.top + margin && p.y < body.bottom - margin;
              const drawn = [...document.querySelectorAll('.connection')].map((svg) => ({ wire: svg.dataset.wire, points: onScreen(svg.querySelector('.main-path')) }));
              const all = drawn.flatMap((w) => w.points);
              const clear = (p, of) => of.every((q) => Math.hypot(q.x - p.x, q.y - p.y) > 16);
              let crossing = null;
              for (const w of drawn.filter((x) => !x.wire.includes('walls_right.'))) {
                const others = drawn.filter((x) => x !== w).flatMap((x) => x.points);
                const on = w.points.find((p) => inside(p, 12) && clear(p, others));
                if (on && crossing === null) crossing = { wire: w.wire, x: on.x, y: on.y };
              }
              let free = null;
              for (let y = body.bottom - 10; y > body.top + 10 && free === null; y -= 4) {
                for (let x = body.left + 12; x < body.right - 12 && free === null; x += 6) {
                  if (clear({ x, y }, all)) free = { x, y };
                }
              }
              return { on: crossing, free };
            }
            """);
        Assert.True(points.GetProperty("on").ValueKind == JsonValueKind.Object, "a wire of other nodes crosses walls_right's body in this layout");
        var crossing = points.GetProperty("on").GetProperty("wire").GetString()!;
        output.WriteLine($"{crossing} crosses walls_right's body");
        Assert.True(points.GetProperty("free").ValueKind == JsonValueKind.Object, "walls_right's body has a part no wire crosses");

        await page.Mouse.ClickAsync((float)points.GetProperty("on").GetProperty("x").GetDouble(), (float)points.GetProperty("on").GetProperty("y").GetDouble());
        await page.GetByTestId("side-pane").Locator("h3", new() { HasTextString = "Wire" }).WaitForAsync();
        Assert.Equal(crossing.Replace("->", "→", StringComparison.Ordinal), await page.GetByTestId("side-pane").Locator("p.mono").TextContentAsync());

        await page.Keyboard.PressAsync("Delete");
        await page.Locator($".connection[data-wire='{crossing}']").WaitForAsync(new() { State = WaitForSelectorState.Detached });
        Assert.Equal(wires - 1, await page.Locator(".connection").CountAsync());
        Assert.Equal(1, await page.Locator(".drawflow-node[data-instance=walls_right]").CountAsync());
        Assert.Equal(3, await page.Locator(".drawflow-node").CountAsync());

        await page.GetByTestId("undo").ClickAsync(); // one undo step brings the wire back
        await page.Locator($".connection[data-wire='{crossing}']").WaitForAsync();
        Assert.Equal(wires, await page.Locator(".connection").CountAsync());

        // The node is still picked by its title, and by its body where no wire crosses it.
        await page.Locator(".drawflow-node[data-instance=walls_right] .gn-head").ClickAsync();
        Assert.Equal("walls_right", await page.GetByTestId("instance-name").InputValueAsync());
        await page.Locator(".drawflow-node[data-instance=touch_right] .gn-head").ClickAsync();
        Assert.Equal("touch_right", await page.GetByTestId("instance-name").InputValueAsync());
        await page.Mouse.ClickAsync((float)points.GetProperty("free").GetProperty("x").GetDouble(), (float)points.GetProperty("free").GetProperty("y").GetDouble());
        Assert.Equal("walls_right", await page.GetByTestId("instance-name").InputValueAsync());
        await EditorFixture.CloseEditor(page);
    }

    [Fact]
    public async Task A_graph_with_a_cycle_and_two_other_problems_lists_all_three_each_under_its_node_or_wire()
    {
        File.WriteAllText(Path.Combine(console.Graphs, "three-problems.json"), console.GraphWithThreeProblems());
        var page = await console.OpenEditor();
        await page.GetByTestId("graph-list").SelectOptionAsync("three-problems.json");
        await page.GetByTestId("load").ClickAsync();
        await page.Locator("#message").Filter(new() { HasTextString = "loaded three-problems.json" }).WaitForAsync();

        await page.Locator("[data-testid=problems][data-count='3']").WaitForAsync();
        var lines = await page.Locator("[data-testid=problems] .problem").AllTextContentsAsync();
        Assert.Equal(3, lines.Count);
        Assert.Contains(lines, l => l.StartsWith("scaling_right $.instances[2].settings.ratio: 500 is outside", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.StartsWith("mystery $.instances[7].type: unknown plug-in type 'no_such_type'", StringComparison.Ordinal));
        Assert.Contains(lines, l => l.Contains("$.wires[", StringComparison.Ordinal)
            && EditorFixture.CycleIn(l).Order(StringComparer.Ordinal).SequenceEqual(EditorFixture.CycleOfThree));
        Assert.False(await page.GetByTestId("start").IsEnabledAsync());

        await page.Locator("[data-testid=problems] .problem .target", new() { HasTextString = "mystery" }).ClickAsync(); // picks the node it names
        Assert.Equal("mystery", await page.GetByTestId("instance-name").InputValueAsync());
        await EditorFixture.CloseEditor(page);
    }
}
