using RobotControl.Runtime.Discovery;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Tests.Support;

namespace RobotControl.Runtime.Tests.GraphFiles;

/// <summary>The optional, editor-only <c>layout</c> field of a graph file.</summary>
public sealed class GraphLayoutTests
{
    private static readonly PluginCatalog Catalog = PluginCatalog.FromAssemblies(typeof(ExamplePlugin).Assembly);

    private static string Graph(string layout) => $$"""
        {
          "schema": "robotcontrol/graph/1",
          "instances": [ { "name": "a", "type": "example" }, { "name": "b", "type": "example" } ],
          "wires": [ { "from": "a.out", "to": "b.in" } ]{{layout}}
        }
        """;

    private static LoadedGraph Load(string json) => GraphFile.LoadFromText(json, "/tmp/graph.json", Catalog, TimeProvider.System);

    [Fact]
    public void Positions_load_and_are_written_back_in_whole_pixels()
    {
        var loaded = Load(Graph(""", "layout": { "a": { "x": 10.6, "y": -4 }, "b": { "x": 300, "y": 20 } }"""));
        var saved = GraphFile.ToJson(loaded.Document);
        var reloaded = Load(saved);

        Assert.Equal(new NodePosition(10.6, -4), loaded.Document.Layout!["a"]);
        Assert.Equal(new NodePosition(11, -4), reloaded.Document.Layout!["a"]);
        Assert.Equal(new NodePosition(300, 20), reloaded.Document.Layout!["b"]);
        Assert.Equal(saved, GraphFile.ToJson(reloaded.Document));
    }

    [Fact]
    public void A_file_without_layout_loads_and_saves_without_one()
    {
        var loaded = Load(Graph(string.Empty));

        Assert.Null(loaded.Document.Layout);
        Assert.DoesNotContain("layout", GraphFile.ToJson(loaded.Document), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("""[1, 2]""", "$.layout", "expected an object of node positions")]
    [InlineData("""{ "c": { "x": 1, "y": 2 } }""", "$.layout.c", "no instance named 'c' in $.instances")]
    [InlineData("""{ "robot": { "x": 1, "y": 2 } }""", "$.layout.robot", "no instance named 'robot' in $.instances")]
    [InlineData("""{ "a": { "x": 1, "y": 2, "z": 3 } }""", "$.layout.a.z", "")]
    [InlineData("""{ "a": { "x": "1", "y": 2 } }""", "$.layout.a.x", "")]
    [InlineData("""{ "a": 5 }""", "$.layout.a", "expected an object with the numbers x and y")]
    public void The_layout_is_checked_as_strictly_as_the_rest(string layout, string path, string message)
    {
        var problem = Assert.Single(Assert.Throws<GraphException>(() => Load(Graph(", \"layout\": " + layout))).Problems);

        Assert.Equal(path, problem.Path);
        Assert.Contains(message, problem.Message, StringComparison.Ordinal);
    }
}
