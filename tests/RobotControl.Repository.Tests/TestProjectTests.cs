using RobotControl.TestSupport;

namespace RobotControl.Repository.Tests;

/// <summary>One test project per production project: <c>tests/RobotControl.X.Tests</c> for <c>src/</c> or <c>plugins/RobotControl.X</c>.</summary>
public sealed class TestProjectTests
{
    [Fact]
    public void Every_production_project_has_its_mirrored_test_project_in_the_solution()
    {
        var solution = File.ReadAllText(RepositoryPaths.Of("RobotControl.sln")).Replace('\\', '/');
        var names = DependencyGraph.ProductionProjectFiles().Select(p => Path.GetFileNameWithoutExtension(p)).ToList();
        var missing = names
            .Where(name => !File.Exists(RepositoryPaths.Of($"tests/{name}.Tests/{name}.Tests.csproj"))
                || !solution.Contains($"\"tests/{name}.Tests/{name}.Tests.csproj\"", StringComparison.Ordinal))
            .Order(StringComparer.Ordinal)
            .ToList();

        Assert.Contains("RobotControl.Robot.Control", names);
        Assert.True(missing.Count == 0, $"production projects without tests/<name>.Tests/<name>.Tests.csproj in RobotControl.sln: {string.Join(", ", missing)}");
    }
}
