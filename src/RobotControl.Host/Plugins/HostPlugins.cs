using RobotControl.Bus.Transports;
using RobotControl.Plugins.CoppeliaSim;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;

namespace RobotControl.Host.Plugins;

/// <summary>
/// The one registration of the plug-ins a host ships with (standard, Touch and CoppeliaSim), for every program that runs graphs,
/// with the host's way of opening devices for them (byte links: serial, USB, TCP).
/// </summary>
public static class HostPlugins
{
    /// <summary>The catalogue of the shipped plug-in types, plus the plug-ins in <paramref name="pluginsFolder"/> if given.</summary>
    public static PluginCatalog Catalog(string? pluginsFolder = null)
    {
        var catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly, typeof(CoppeliaSimPlugin).Assembly);
        catalog.DeviceOpener = transport => new LinkByteSource(LinkFactory.Open(transport));
        if (pluginsFolder is not null)
        {
            catalog.AddFolder(pluginsFolder);
        }

        return catalog;
    }
}
