using RobotControl.Runtime.Discovery;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Link.Tests.Reference;

/// <summary>
/// The link plug-ins' ports and settings (names, units, initial and safe values, descriptions, ranges, defaults) are
/// exactly what <c>docs/plugin-reference.md</c> tells the engineer wiring a graph.
/// </summary>
public sealed class LinkReferenceTests
{
    [Theory]
    [InlineData("link_out")]
    [InlineData("link_in")]
    public void The_kept_reference_describes_the_link_plugin_as_it_declares_itself(string name)
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(LinkOutPlugin).Assembly);
        var description = PluginDescription.Of(catalog.Find(name)!, ShippedRobots.Lb, RepositoryPaths.Root);
        var section = PluginReference.Section(description);
        var kept = File.ReadAllText(RepositoryPaths.Of("docs/plugin-reference.md")).ReplaceLineEndings("\n");

        Assert.Equal(2, catalog.Types.Count);
        Assert.True(
            kept.Contains(section, StringComparison.Ordinal),
            $"docs/plugin-reference.md: the section of '{name}' differs from what the plug-in declares (regenerate the file with the command at its top):\n{section}");
    }
}
