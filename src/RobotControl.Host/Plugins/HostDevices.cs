using RobotControl.Bus.Transports;
using RobotControl.Plugins.Sdk.Devices;

namespace RobotControl.Host.Plugins;

/// <summary>
/// The host's way of opening devices for plug-ins: a plug-in asks <c>PluginContext.OpenDevice(transport)</c> for an
/// <see cref="IByteSource"/> and the host opens the byte link (serial, USB, TCP) behind it, so plug-ins (the foot
/// pedals) need no reference to the bus layer. Whoever assembles a plug-in catalogue sets it as the catalogue's
/// <c>DeviceOpener</c>.
/// </summary>
public static class HostDevices
{
    /// <summary>Opens the byte link <paramref name="transport"/> names (e.g. <c>serial:/dev/ttyUSB1?baud=115200</c>).</summary>
    /// <exception cref="FormatException">The transport is malformed.</exception>
    public static IByteSource Open(string transport) => new LinkByteSource(LinkFactory.Open(transport));
}
