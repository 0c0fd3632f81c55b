using RobotControl.Definitions.Json;
using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Tests.Support;

namespace RobotControl.Runtime.Tests.GraphFiles;

public sealed class GraphSettingOverridesTests
{
    private static readonly PluginCatalog Catalog = PluginCatalog.FromAssemblies(typeof(ExamplePlugin).Assembly);

    private const string Graph = """
        {
          "schema": "robotcontrol/graph/1",
          "instances": [
            { "name": "a", "type": "example", "settings": { "ratio": 0.25 } },
            { "name": "b", "type": "example" }
          ],
          "wires": [ { "from": "a.out", "to": "b.in" } ]
        }
        """;

    private static LoadedGraph Load(params string[] sets)
    {
        var path = Path.Combine(Path.GetTempPath(), $"overrides-{Guid.NewGuid():N}.json");
        File.WriteAllText(path, Graph);
        try
        {
            return GraphFile.Load(path, Catalog, TimeProvider.System, [.. sets.Select(SettingOverride.Parse)]);
        }
        finally
        {
            File.Delete(path);
        }
    }

    [Fact]
    public void Overrides_replace_settings_by_their_kind_and_add_settings_an_instance_did_not_have()
    {
        var loaded = Load("a.ratio=0.5", "b.samples=7", "b.mode=hold_last_finite", "b.script=x=1.csv");
        var a = (ExampleSettings)loaded.Document.Instances[0].Settings!;
        var b = (ExampleSettings)loaded.Document.Instances[1].Settings!;
        Assert.Equal(0.5, a.Ratio);
        Assert.Equal(7, b.Samples);
        Assert.Equal(RobotControl.Plugins.Sdk.Ports.SafeValue.HoldLastFinite, b.Mode);
        Assert.EndsWith("x=1.csv", b.Script, StringComparison.Ordinal);
    }

    [Fact]
    public void An_overridden_value_gets_the_loaders_own_message_and_json_path_named_by_its_override()
    {
        var problems = Assert.Throws<GraphException>(() => Load("a.ratio=5", "b.samples=two", "a.nope=1")).Problems.Select(p => p.ToString()).ToList();
        Assert.Contains(problems, p => p.StartsWith("--set a.ratio=5: $.instances[0].settings.ratio: 5 is outside 0.05..1", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("--set b.samples=two: $.instances[1].settings.samples: expected an integer, found string", StringComparison.Ordinal));
        Assert.Contains(problems, p => p.StartsWith("--set a.nope=1: $.instances[0].settings.nope: unknown setting", StringComparison.Ordinal));
    }

    [Theory]
    [InlineData("NaN")]
    [InlineData("Infinity")]
    [InlineData("-Infinity")]
    public void A_non_finite_number_for_a_number_setting_is_named_with_its_override(string value)
    {
        var ex = Assert.Throws<GraphException>(() => Load($"a.ratio={value}"));

        var problem = Assert.Single(ex.Problems);
        Assert.Equal($"--set a.ratio={value}", problem.Path);
        Assert.Equal($"'{value}' is not a finite number", problem.Message);
    }

    [Fact]
    public void An_unknown_instance_is_named_with_the_instances_there_are()
    {
        var ex = Assert.Throws<GraphException>(() => Load("sim.endpoint=tcp://127.0.0.1:1"));
        var problem = Assert.Single(ex.Problems);
        Assert.Equal("--set sim.endpoint=tcp://127.0.0.1:1", problem.Path);
        Assert.Equal("no instance named 'sim' (instances: a, b)", problem.Message);
    }

    [Fact]
    public void An_unknown_instance_is_reported_with_the_loaders_problems()
    {
        var problems = Assert.Throws<GraphException>(() => Load("ghost.x=1", "a.ratio=5")).Problems.Select(p => p.ToString()).ToList();
        Assert.Equal(2, problems.Count);
        Assert.Equal("--set ghost.x=1: no instance named 'ghost' (instances: a, b)", problems[0]);
        Assert.StartsWith("--set a.ratio=5: $.instances[0].settings.ratio: 5 is outside 0.05..1", problems[1], StringComparison.Ordinal);
    }

    [Fact]
    public void Without_overrides_the_text_is_untouched()
    {
        var problems = new List<JsonProblem>();
        Assert.Same(Graph, GraphSettingOverrides.Apply(Graph, [], Catalog, "/tmp/g.json", problems));
        Assert.Empty(problems);
    }

    [Theory]
    [InlineData("sim.endpoint")]
    [InlineData("endpoint=1")]
    [InlineData(".endpoint=1")]
    [InlineData("sim.=1")]
    public void A_malformed_set_is_one_line_naming_the_option(string text)
    {
        var ex = Assert.Throws<FormatException>(() => SettingOverride.Parse(text));
        Assert.Equal($"--set '{text}': expected <instance>.<setting>=<value>, e.g. sim.endpoint=tcp://127.0.0.1:23456", ex.Message);
    }

    [Fact]
    public void The_value_keeps_dots_and_equals_signs()
    {
        Assert.Equal(new SettingOverride("sim", "endpoint", "tcp://127.0.0.1:23456"), SettingOverride.Parse("sim.endpoint=tcp://127.0.0.1:23456"));
    }
}
