using RobotControl.Host.Plugins;
using RobotControl.Plugins.CoppeliaSim;
using RobotControl.Plugins.Link;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Cli;

/// <summary>
/// The one registration of the plug-ins <c>robotctl</c> ships with (standard, Touch, CoppeliaSim and the NATS link), for every
/// command that runs graphs (and the bench, which runs what <c>robotctl</c> runs), with the host's way of opening
/// devices for them (<see cref="HostDevices"/>). The session layer takes the catalogue from its caller and knows no
/// concrete plug-in.
/// </summary>
internal static class ShippedPlugins
{
    /// <summary>The catalogue of the shipped plug-in types, plus the plug-ins in <paramref name="pluginsFolder"/> if given.</summary>
    public static PluginCatalog Catalog(string? pluginsFolder = null)
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly, typeof(CoppeliaSimPlugin).Assembly, typeof(LinkOutPlugin).Assembly);
        catalog.DeviceOpener = HostDevices.Open;
        if (pluginsFolder is not null)
        {
            catalog.AddFolder(pluginsFolder);
        }

        return catalog;
    }
}
