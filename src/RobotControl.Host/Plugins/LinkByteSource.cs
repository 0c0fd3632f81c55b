using RobotControl.Bus.Transports;
using RobotControl.Plugins.Sdk.Devices;

namespace RobotControl.Host.Plugins;

/// <summary>A device's bytes on a byte link (serial, USB, TCP), for plug-ins: the host's side of <see cref="IByteSource"/>.</summary>
internal sealed class LinkByteSource(IByteLink link) : IByteSource
{
    public int Read(Span<byte> buffer, TimeSpan timeout) => link.Read(buffer, timeout);

    public void Dispose() => link.Dispose();
}
