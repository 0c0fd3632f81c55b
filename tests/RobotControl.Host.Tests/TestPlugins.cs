using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Host.Tests;

/// <summary>The plug-ins the shipped teleop graph uses (standard and Touch): the session layer takes its catalogue from its caller and knows none itself.</summary>
internal static class TestPlugins
{
    public static PluginCatalog Catalog() => PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly);
}
