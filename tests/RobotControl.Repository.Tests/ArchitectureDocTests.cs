using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>docs/architecture.md pictures the project references as the .csproj files declare them.</summary>
public sealed class ArchitectureDocTests
{
    private const string WriteVariable = "ROBOTCONTROL_WRITE_DEPS_GRAPH";

    [Fact]
    public void The_dependency_graph_in_the_architecture_doc_matches_the_project_files()
    {
        var file = RepositoryPaths.Of("docs/architecture.md");
        var document = File.ReadAllText(file).ReplaceLineEndings("\n");
        var expected = DependencyGraph.Generate();
        var current = DependencyGraph.Current(document);

        // tools/deps-graph.sh sets the variable to rewrite the block in place.
        if (Environment.GetEnvironmentVariable(WriteVariable) == "1" && current is not null && current != expected)
        {
            File.WriteAllText(file, document.Replace(current, expected, StringComparison.Ordinal));
            current = expected;
        }

        Assert.True(
            current == expected,
            $"docs/architecture.md's dependency graph differs from the .csproj files; run `bash tools/deps-graph.sh`, or replace the block with:\n{expected}");
    }

    [Fact]
    public void The_generated_graph_has_every_production_project_and_its_references()
    {
        var graph = DependencyGraph.Generate();

        Assert.Contains("  Definitions[\"RobotControl.Definitions\"]\n", graph, StringComparison.Ordinal);
        Assert.Contains("  Plugins_Touch[\"RobotControl.Plugins.Touch\"]\n", graph, StringComparison.Ordinal);
        Assert.Contains("  Kinematics --> Definitions\n", graph, StringComparison.Ordinal);
        Assert.DoesNotContain("Tests", graph, StringComparison.Ordinal);
    }
}
