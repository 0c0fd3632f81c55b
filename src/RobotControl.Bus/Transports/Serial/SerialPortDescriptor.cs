using System.IO.Ports;
using System.Reflection;
using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// The file descriptor System.IO.Ports opened for a <see cref="SerialPort"/>. SerialPort does not expose it, and its
/// stream on Unix queues every read and write to a background I/O loop (a request and a Task per call, 1 ms poll
/// steps), which the allocation-free bus cycle cannot use; so <see cref="SerialLink"/> moves the bytes itself on this
/// descriptor while SerialPort keeps opening, configuring, draining and closing the port.
/// </summary>
internal static class SerialPortDescriptor
{
    // SerialStream's handle field in System.IO.Ports 10.0.x (Directory.Packages.props pins the version; the serial
    // tests fail if an update renames it).
    private const string HandleField = "_handle";

    /// <summary>The open port's handle, with a reference added (release it before closing the port).</summary>
    /// <exception cref="IOException">This System.IO.Ports build keeps its descriptor elsewhere.</exception>
    public static SafeHandle Acquire(SerialPort port)
    {
        ArgumentNullException.ThrowIfNull(port);
        var stream = port.BaseStream;
        var field = stream.GetType().GetField(HandleField, BindingFlags.Instance | BindingFlags.NonPublic);
        if (field?.GetValue(stream) is not SafeHandle { IsInvalid: false, IsClosed: false } handle)
        {
            var version = typeof(SerialPort).Assembly.GetName().Version;
            throw new IOException($"serial {port.PortName}: cannot reach the descriptor System.IO.Ports {version} opened ({stream.GetType().Name}.{HandleField}); the serial link was written against System.IO.Ports 10.0.14");
        }

        var added = false;
        handle.DangerousAddRef(ref added);
        return handle;
    }
}
