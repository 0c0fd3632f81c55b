namespace RobotControl.Plugins.Sdk.Devices;

/// <summary>
/// Bytes from a device a plug-in reads on a thread of its own (a pedal box on a serial line, say). The host opens it
/// from a transport string (<see cref="PluginContext.OpenDevice"/>), so a plug-in needs no transport code of its own.
/// </summary>
public interface IByteSource : IDisposable
{
    /// <summary>Waits up to <paramref name="timeout"/> for bytes and copies those that came into <paramref name="buffer"/>; 0 when none did.</summary>
    /// <exception cref="IOException">The device is gone.</exception>
    int Read(Span<byte> buffer, TimeSpan timeout);
}
