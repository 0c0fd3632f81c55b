using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Tests.Support;

namespace RobotControl.Runtime.Tests.GraphFiles;

public sealed class GraphFileTests
{
    private static readonly PluginCatalog Catalog = PluginCatalog.FromAssemblies(typeof(ExamplePlugin).Assembly);

    private static GraphException LoadFails(string json) =>
        Assert.Throws<GraphException>(() => GraphFile.LoadFromText(json, "/tmp/graph.json", Catalog, TimeProvider.System));

    [Fact]
    public void A_valid_file_loads_and_saving_writes_back_what_was_loaded()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "transport": "virtual",
              "loop_rate_hz": 500,
              "instances": [
                { "name": "a", "type": "example", "settings": { "ratio": 0.25, "reference_x_mm": 3, "mode": "hold_last_finite" } },
                { "name": "b", "type": "example" }
              ],
              "wires": [
                { "from": "a.out", "to": "b.in" },
                { "from": "b.out", "to": "a.in", "delayed": true }
              ]
            }
            """;

        var loaded = GraphFile.LoadFromText(json, "/tmp/graph.json", Catalog, TimeProvider.System);
        var saved = GraphFile.ToJson(loaded.Document);
        var reloaded = GraphFile.LoadFromText(saved, "/tmp/graph.json", Catalog, TimeProvider.System);

        Assert.Equal(500, loaded.Document.LoopRateHz);
        Assert.Equal(0.25, ((ExampleSettings)loaded.Document.Instances[0].Settings!).Ratio);
        Assert.Equal(RobotControl.Plugins.Sdk.Ports.SafeValue.HoldLastFinite, ((ExampleSettings)loaded.Document.Instances[0].Settings!).Mode);
        Assert.Equal(loaded.Document.Instances, reloaded.Document.Instances);
        Assert.Equal(loaded.Document.Wires.Select(w => (w.From, w.To, w.Delayed)), reloaded.Document.Wires.Select(w => (w.From, w.To, w.Delayed)));
        Assert.Equal(saved, GraphFile.ToJson(reloaded.Document));
        Assert.Contains("\"reference_x_mm\": 3", saved, StringComparison.Ordinal);
        Assert.Contains("\"delayed\": true", saved, StringComparison.Ordinal);

        // Only what the author chose: a's four as the file gave them, the required script; b's settings at their
        // defaults, which the file did not name, are not expanded.
        var written = System.Text.Json.Nodes.JsonNode.Parse(saved)!["instances"]!.AsArray();
        Assert.Equal(["ratio", "reference_x_mm", "mode", "script"], written[0]!["settings"]!.AsObject().Select(p => p.Key));
        Assert.Equal(["script"], written[1]!["settings"]!.AsObject().Select(p => p.Key));
    }

    [Fact]
    public void Saving_keeps_a_setting_the_file_gave_at_its_default_and_leaves_out_the_defaults_it_did_not_name()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "instances": [ { "name": "a", "type": "example", "settings": { "ratio": 0.5, "samples": 3 } } ],
              "wires": []
            }
            """;

        var saved = GraphFile.ToJson(GraphFile.LoadFromText(json, "/tmp/graph.json", Catalog, TimeProvider.System).Document);

        var settings = System.Text.Json.Nodes.JsonNode.Parse(saved)!["instances"]![0]!["settings"]!.AsObject();
        Assert.Equal(["ratio", "samples", "script"], settings.Select(p => p.Key)); // ratio 0.5 is the default, given: kept
        Assert.Equal(0.5, (double)settings["ratio"]!);
    }

    [Fact]
    public void Save_then_load_gives_the_same_graph()
    {
        var robot = Repo.Path("hardware/robots/lb-1.0.json").Replace("\\", "/", StringComparison.Ordinal);
        var json = $$"""
            {
              "schema": "robotcontrol/graph/1",
              "robot": "{{robot}}",
              "transport": "virtual",
              "loop_rate_hz": 250,
              "instances": [
                { "name": "a", "type": "example", "settings": { "ratio": 0.5, "reference_x_mm": -7.25, "mode": "hold_last_finite" } },
                { "name": "b", "type": "example" }
              ],
              "wires": [
                { "from": "a.out", "to": "b.in" },
                { "from": "b.out", "to": "a.in", "delayed": true }
              ]
            }
            """;
        var folder = Directory.CreateTempSubdirectory("graph-save-");
        try
        {
            var first = GraphFile.LoadFromText(json, Path.Combine(folder.FullName, "written.json"), Catalog, TimeProvider.System).Document;
            var file = Path.Combine(folder.FullName, "saved.json");
            GraphFile.Save(first, file);
            var second = GraphFile.Load(file, Catalog, TimeProvider.System).Document;

            Assert.Equal(first.Robot, second.Robot);
            Assert.Equal(first.Transport, second.Transport);
            Assert.Equal(first.LoopRateHz, second.LoopRateHz);
            Assert.Equal(first.Instances, second.Instances);
            Assert.Equal(first.Wires.Select(w => (w.From, w.To, w.Delayed)), second.Wires.Select(w => (w.From, w.To, w.Delayed)));
            Assert.Equal(-7.25, ((ExampleSettings)second.Instances[0].Settings!).ReferenceXMm);
        }
        finally
        {
            folder.Delete(recursive: true);
        }
    }

    [Fact]
    public void Every_problem_is_reported_with_its_json_path()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "instances": [
                { "name": "a", "type": "example", "settings": { "ratio": 5, "nope": 1, "samples": "two" } },
                { "name": "b", "type": "no_such_type" },
                { "name": "c", "type": "example" },
                { "name": "c", "type": "example" },
                { "name": "d", "type": "example", "settings": { "mode": "sideways", "script": "" } }
              ],
              "wires": [
                { "from": "c.missing", "to": "c.in" },
                { "from": "c.out", "to": "c.nothing" },
                { "from": "c.in", "to": "c.in" },
                { "from": "c.out", "to": "c.in", "delayed": "yes" }
              ]
            }
            """;

        var problems = LoadFails(json).Problems.Select(p => p.ToString()).ToList();

        Assert.Contains(problems, p => p.StartsWith("$.instances[0].settings.ratio: 5 is outside 0.05..1", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[0].settings.nope: unknown setting", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[0].settings.samples: expected an integer, found string", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[1].type: unknown plug-in type 'no_such_type' (known: example)", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[3].name: duplicate instance name 'c'", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[4].settings.mode: 'sideways' is not one of hold_last_finite, zero, initial", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[0].from: unknown output 'c.missing'", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[1].to: unknown input 'c.nothing'", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[2].from: 'c.in' is an input", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[3].delayed: expected true or false", StringComparison.Ordinal));
    }

    [Fact]
    public void A_cycle_is_reported_at_the_wire_that_closes_it()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "instances": [ { "name": "a", "type": "example" }, { "name": "b", "type": "example" } ],
              "wires": [ { "from": "a.out", "to": "b.in" }, { "from": "b.out", "to": "a.in" } ]
            }
            """;

        var problem = Assert.Single(LoadFails(json).Problems);

        Assert.StartsWith("$.wires[", problem.Path, StringComparison.Ordinal);
        Assert.Contains("cycle without a delayed wire", problem.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_cycle_is_listed_with_the_other_problems_of_the_file_naming_its_instances()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "instances": [
                { "name": "a", "type": "example" },
                { "name": "b", "type": "example" },
                { "name": "c", "type": "no_such_type" },
                { "name": "d", "type": "example", "settings": { "ratio": 5 } }
              ],
              "wires": [ { "from": "a.out", "to": "b.in" }, { "from": "b.out", "to": "a.in" } ]
            }
            """;

        var problems = LoadFails(json).Problems.Select(p => p.ToString()).ToList();

        Assert.Equal(3, problems.Count);
        Assert.Contains(problems, p => p.StartsWith("$.instances[2].type: unknown plug-in type 'no_such_type'", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.instances[3].settings.ratio: 5 is outside", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.wires[", StringComparison.Ordinal) && (p.Contains("cycle without a delayed wire: a -> b -> a", StringComparison.Ordinal) || p.Contains("cycle without a delayed wire: b -> a -> b", StringComparison.Ordinal)));
    }

    [Fact]
    public void Two_separate_cycles_are_both_named()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "instances": [ { "name": "a", "type": "example" }, { "name": "b", "type": "example" }, { "name": "c", "type": "example" }, { "name": "d", "type": "example" } ],
              "wires": [ { "from": "a.out", "to": "b.in" }, { "from": "b.out", "to": "a.in" }, { "from": "c.out", "to": "d.in" }, { "from": "d.out", "to": "c.in" } ]
            }
            """;

        var problems = LoadFails(json).Problems;

        Assert.Equal(2, problems.Count);
        Assert.Single(problems, p => p.Message.Contains("cycle without a delayed wire: a -> b -> a", StringComparison.Ordinal) || p.Message.Contains("cycle without a delayed wire: b -> a -> b", StringComparison.Ordinal));
        Assert.Single(problems, p => p.Message.Contains("cycle without a delayed wire: c -> d -> c", StringComparison.Ordinal) || p.Message.Contains("cycle without a delayed wire: d -> c -> d", StringComparison.Ordinal));
    }

    [Fact]
    public void Cross_setting_rules_and_unknown_top_level_fields_are_reported()
    {
        const string json = """
            {
              "schema": "robotcontrol/graph/1",
              "loop_rate_hz": 0,
              "extra": true,
              "instances": [ { "name": "a", "type": "example", "settings": { "samples": 6, "ratio": 1.0 } } ]
            }
            """;

        var problems = LoadFails(json).Problems.Select(p => p.ToString()).ToList();

        Assert.Contains("$.instances[0].settings.samples: more than 5 samples need a ratio of at most 0.9", problems);
        Assert.Contains(problems, p => p.StartsWith("$.extra: unknown field", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("$.loop_rate_hz:", StringComparison.Ordinal));
    }

    [Fact]
    public void The_catalog_finds_plugin_types_by_name_with_their_settings_schema()
    {
        var type = Catalog.Find("example");

        Assert.NotNull(type);
        Assert.Equal("A test plug-in with settings.", type.Description);
        var ratio = type.Settings!.Settings.Single(s => s.JsonName == "ratio");
        Assert.Equal((0.05, 1.0, 0.5), (ratio.Minimum, ratio.Maximum, (double)ratio.DefaultValue!));
        Assert.Equal("mm", type.Settings.Settings.Single(s => s.JsonName == "reference_x_mm").Units);
    }
}
