using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.TestSupport;

namespace RobotControl.Plugins.Touch.Tests.Reference;

/// <summary>
/// The touch plug-in's ports and settings (names, units, initial and safe values, descriptions, ranges, defaults) are
/// exactly what <c>docs/plugin-reference.md</c> tells the engineer wiring a graph: described, as that file is, with
/// the settings of <c>touch_right</c> in <c>graphs/teleop-lb.json</c>.
/// </summary>
public sealed class TouchReferenceTests
{
    [Fact]
    public void The_kept_reference_describes_the_touch_as_it_declares_itself()
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(TouchPlugin).Assembly);
        var type = Assert.Single(catalog.Types);
        var example = PluginExample.FromGraph(RepositoryPaths.Of("graphs/teleop-lb.json"), catalog)[type.Name];
        var description = PluginDescription.Of(type, ShippedRobots.Lb, RepositoryPaths.Root, example);
        var section = PluginReference.Section(description);
        var kept = File.ReadAllText(RepositoryPaths.Of("docs/plugin-reference.md")).ReplaceLineEndings("\n");

        Assert.Equal("touch_right in teleop-lb.json", description.PortsFrom);
        Assert.Contains("| `button1` |", section, StringComparison.Ordinal);
        Assert.True(
            kept.Contains(section, StringComparison.Ordinal),
            $"docs/plugin-reference.md: the section of 'touch' differs from what the plug-in declares (regenerate the file with the command at its top):\n{section}");
    }
}
