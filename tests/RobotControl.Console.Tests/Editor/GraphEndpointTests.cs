using System.Net;
using System.Net.Http.Json;
using System.Text.Json;
using System.Text.Json.Nodes;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;

namespace RobotControl.WebConsole.Tests.Editor;

/// <summary>The graph editor's API: palette, checks by the loader itself, load and save inside the graphs folder only.</summary>
[Collection(EditorCollection.Name)]
public sealed class GraphEndpointTests(EditorFixture console)
{
    [Fact]
    public async Task The_catalog_lists_every_type_with_ports_units_and_settings_schema()
    {
        using var http = console.Client("catalog");
        var catalog = await http.GetFromJsonAsync<JsonElement>("api/editor/catalog");
        var types = catalog.GetProperty("types").EnumerateArray().ToDictionary(t => t.GetProperty("name").GetString()!);

        Assert.Equal(ConsoleFixture.Catalog().Types.Select(t => t.Name).Order(StringComparer.Ordinal), types.Keys);
        var scaling = types["scaling"];
        Assert.Equal("Scales displacement from a reference point by a ratio.", scaling.GetProperty("description").GetString());
        var x = scaling.GetProperty("ports").GetProperty("inputs").EnumerateArray().First(p => p.GetProperty("name").GetString() == "x");
        Assert.Equal("mm", x.GetProperty("units").GetString());
        var ratio = scaling.GetProperty("settings").EnumerateArray().First(s => s.GetProperty("name").GetString() == "ratio");
        Assert.Equal("number", ratio.GetProperty("kind").GetString());
        Assert.True(ratio.GetProperty("minimum").GetDouble() < ratio.GetProperty("maximum").GetDouble());
        Assert.False(string.IsNullOrEmpty(ratio.GetProperty("description").GetString()));
        var robotInputs = catalog.GetProperty("robot").GetProperty("inputs").EnumerateArray().Select(p => p.GetProperty("name").GetString()).ToList();
        Assert.Contains("right.elbow", robotInputs);
    }

    [Fact]
    public async Task A_check_reports_exactly_what_the_graph_file_loader_reports()
    {
        var text = BrokenGraph();
        var expected = Assert.Throws<GraphException>(() => GraphFile.LoadFromText(text, Path.Combine(console.Graphs, "untitled.json"), ConsoleFixture.Catalog(), TimeProvider.System)).Problems;

        using var http = console.Client("check");
        var reply = await http.PostAsJsonAsync("api/editor/check", new { graph = JsonNode.Parse(text) });
        reply.EnsureSuccessStatusCode();
        var problems = (await reply.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("problems").EnumerateArray()
            .Select(p => (p.GetProperty("path").GetString(), p.GetProperty("message").GetString())).ToList();

        Assert.Equal(expected.Select(p => ((string?)p.Path, (string?)p.Message)), problems);
        Assert.Contains(problems, p => p.Item1 == "$.instances[2].settings.ratio");
    }

    [Theory]
    [InlineData("../escape.json")]
    [InlineData("/tmp/escape.json")]
    [InlineData("sub/escape.json")]
    [InlineData("escape.txt")]
    public async Task Saving_outside_the_graphs_folder_is_refused_with_one_line(string name)
    {
        using var http = await console.Operator("save");
        var reply = await http.PutAsJsonAsync($"api/editor/graphs/{Uri.EscapeDataString(name)}", new { graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten))) });

        Assert.Equal(HttpStatusCode.BadRequest, reply.StatusCode);
        var error = (await reply.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("error").GetString()!;
        Assert.DoesNotContain('\n', error);
        Assert.True(error.StartsWith($"graph '{name}':", StringComparison.Ordinal), error);
        Assert.False(File.Exists(Path.Combine(console.Root, "escape.json")));
    }

    [Fact]
    public async Task A_graph_with_problems_is_neither_saved_nor_started()
    {
        using var http = await console.Operator("refused");
        var reply = await http.PutAsJsonAsync("api/editor/graphs/broken.json", new { graph = JsonNode.Parse(BrokenGraph()) });
        Assert.Equal(HttpStatusCode.UnprocessableEntity, reply.StatusCode);
        Assert.False(File.Exists(Path.Combine(console.Graphs, "broken.json")));

        var start = await http.PostAsJsonAsync("api/editor/start", new { name = "broken.json", graph = JsonNode.Parse(BrokenGraph()) });
        Assert.Equal(HttpStatusCode.UnprocessableEntity, start.StatusCode);
        var body = await start.Content.ReadFromJsonAsync<JsonElement>();
        Assert.Contains(body.GetProperty("details").EnumerateArray(), d => d.GetString()!.StartsWith("$.instances[2].settings.ratio: ", StringComparison.Ordinal));
        await http.DeleteAsync("api/operator");
    }

    [Fact]
    public async Task Saving_writes_with_the_loaders_writer_and_keeps_the_layout()
    {
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        graph["layout"] = new JsonObject { ["clutch_right"] = new JsonObject { ["x"] = 420.4, ["y"] = 80 }, ["robot"] = new JsonObject { ["x"] = 900, ["y"] = 40 } };
        using var http = await console.Operator("save-ok");

        var reply = await http.PutAsJsonAsync("api/editor/graphs/saved-by-api.json", new { graph });
        reply.EnsureSuccessStatusCode();

        var path = Path.Combine(console.Graphs, "saved-by-api.json");
        var loaded = GraphFile.Load(path, ConsoleFixture.Catalog(), TimeProvider.System);
        Assert.Equal(GraphFile.ToJson(loaded.Document), File.ReadAllText(path));
        Assert.Equal(new NodePosition(420, 80), loaded.Document.Layout!["clutch_right"]);
        Assert.Equal(graph["wires"]!.AsArray().Count, loaded.Document.Wires.Count); // all 42 of the hand-written file
        var text = await http.GetStringAsync("api/editor/graphs/saved-by-api.json");
        Assert.Equal(File.ReadAllText(path), text);
        Assert.Contains("saved-by-api.json", (await http.GetFromJsonAsync<JsonElement>("api/editor/graphs")).GetProperty("graphs").EnumerateArray().Select(g => g.GetString()));
    }

    [Fact]
    public async Task A_cycle_without_a_delayed_wire_is_reported_at_the_wire()
    {
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        var wires = graph["wires"]!.AsArray();
        var index = wires.Select((w, i) => (w, i)).First(x => (string?)x.w!["from"] == "damping_right.fx").i;
        wires[index]!.AsObject().Remove("delayed");
        using var http = console.Client("cycle");

        var reply = await http.PostAsJsonAsync("api/editor/check", new { name = "cycle.json", graph });

        var problem = Assert.Single((await reply.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("problems").EnumerateArray());
        Assert.StartsWith("$.wires[", problem.GetProperty("path").GetString());
        Assert.Contains("cycle without a delayed wire", problem.GetProperty("message").GetString());
    }

    [Fact]
    public async Task A_check_lists_a_cycle_together_with_the_other_problems_naming_the_cycles_instances()
    {
        using var http = console.Client("all-problems");

        var reply = await http.PostAsJsonAsync("api/editor/check", new { name = "three.json", graph = JsonNode.Parse(console.GraphWithThreeProblems()) });

        reply.EnsureSuccessStatusCode();
        var problems = (await reply.Content.ReadFromJsonAsync<JsonElement>()).GetProperty("problems").EnumerateArray()
            .Select(p => $"{p.GetProperty("path").GetString()}: {p.GetProperty("message").GetString()}").ToList();
        Assert.True(problems.Count == 3, string.Join("\n", problems));
        Assert.Contains(problems, p => p.StartsWith("$.instances[2].settings.ratio: 500 is outside", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[7].type: unknown plug-in type 'no_such_type'", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[", StringComparison.Ordinal)
            && EditorFixture.CycleIn(p).Order(StringComparer.Ordinal).SequenceEqual(EditorFixture.CycleOfThree));
    }

    [Fact]
    public async Task Start_runs_the_graph_behind_the_same_session_and_stop_turns_it_off()
    {
        var run = await console.Runner.StartAsync(Path.Combine(console.Graphs, EditorFixture.HandWritten));
        Assert.True(run.Running, run.Problem);
        Assert.Equal(EditorFixture.HandWritten, Path.GetFileName(console.Session.Status.Graph));
        Assert.Contains("touch_right.x", console.Session.Signals.Names);
        Assert.DoesNotContain("touch_left.x", console.Session.Signals.Names);

        run = await console.Runner.StopAsync();
        Assert.False(run.Running);
        Assert.Equal("stopped", console.Session.Status.Session);
        Assert.False(console.Session.Status.TorqueOn);
        Assert.Equal("stopped: torque off on all 6 modules (read back)", console.Session.EventsAfter(0)[^1].Message); // the stop's read-back, for the pages
        var end = console.Session.Current.Close(); // the stopped graph's end, as robotctl console reports it (closing the console itself would end the shared fixture)
        Assert.True(end.TorqueOff);
        Assert.Equal(6, end.Stop!.Modules);
        using var http = console.Client("stopped");
        Assert.Empty(await http.GetFromJsonAsync<JsonElement[]>("api/controllers") ?? []);
    }

    /// <summary>The one-arm graph with an out-of-range ratio and a feedback wire no longer delayed.</summary>
    private string BrokenGraph()
    {
        var graph = JsonNode.Parse(File.ReadAllText(Path.Combine(console.Graphs, EditorFixture.HandWritten)))!.AsObject();
        graph["instances"]![2]!["settings"]!["ratio"] = 500;
        foreach (var wire in graph["wires"]!.AsArray())
        {
            if ((string?)wire!["from"] == "damping_right.fx")
            {
                wire.AsObject().Remove("delayed");
            }
        }

        return graph.ToJsonString();
    }
}
