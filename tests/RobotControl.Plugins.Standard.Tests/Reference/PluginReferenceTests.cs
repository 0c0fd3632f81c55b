using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Runtime.Discovery;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Standard.Tests.Reference;

/// <summary>
/// Each standard plug-in's ports and settings (names, units, initial and safe values, descriptions, ranges, defaults)
/// are exactly what <c>docs/plugin-reference.md</c> tells the engineer wiring a graph.
/// </summary>
public sealed class PluginReferenceTests
{
    public static TheoryData<string> StandardTypes()
    {
        var data = new TheoryData<string>();
        foreach (var type in Catalog.Types)
        {
            data.Add(type.Name);
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(StandardTypes))]
    public void The_kept_reference_describes_the_plugin_as_it_declares_itself(string name)
    {
        var description = PluginDescription.Of(Catalog.Find(name)!, ShippedRobots.Lb, RepositoryPaths.Root);
        var kept = File.ReadAllText(RepositoryPaths.Of("docs/plugin-reference.md")).ReplaceLineEndings("\n");
        var section = PluginReference.Section(description).TrimEnd('\n') + "\n"; // the last section ends the file

        Assert.True(
            kept.Contains(section, StringComparison.Ordinal),
            $"docs/plugin-reference.md: the section of '{name}' differs from what the plug-in declares (regenerate the file with the command at its top):\n{section}");
    }

    [Fact]
    public void Every_standard_type_is_in_the_reference()
    {
        Assert.True(Catalog.Types.Count >= 10, $"{Catalog.Types.Count} types found in the standard assembly");
        var kept = File.ReadAllText(RepositoryPaths.Of("docs/plugin-reference.md"));
        Assert.All(Catalog.Types, t => Assert.Contains($"\n## {t.Name}\n", kept.ReplaceLineEndings("\n"), StringComparison.Ordinal));
    }

    private static PluginCatalog Catalog { get; } = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly);
}
