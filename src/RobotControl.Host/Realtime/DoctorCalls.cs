using System.Runtime.InteropServices;

namespace RobotControl.Host.Realtime;

/// <summary>The libc calls of <see cref="Doctor"/>: a serial port's <c>serial_struct</c> flags (TIOCGSERIAL).</summary>
internal static partial class DoctorCalls
{
    public const int AsyncLowLatency = 1 << 13;
    private const int ORdWrNoCttyNonBlock = 0x2 | 0x100 | 0x800;
    private const nuint TiocGSerial = 0x541E;
    private const int FlagsOffset = 16; // int type, int line, uint port, int irq, int flags

    /// <summary>The port's serial_struct flags (null: the device has none, e.g. a pseudo-terminal).</summary>
    public static int? SerialFlags(string device)
    {
        var fd = Open(device, ORdWrNoCttyNonBlock);
        if (fd < 0)
        {
            return null;
        }

        try
        {
            var buffer = new byte[128];
            return Ioctl(fd, TiocGSerial, buffer) == 0 ? BitConverter.ToInt32(buffer, FlagsOffset) : null;
        }
        finally
        {
            _ = Close(fd);
        }
    }

    [LibraryImport("libc", EntryPoint = "open", SetLastError = true, StringMarshalling = StringMarshalling.Utf8)]
    private static partial int Open(string path, int flags);

    [LibraryImport("libc", EntryPoint = "close", SetLastError = true)]
    private static partial int Close(int fd);

    [LibraryImport("libc", EntryPoint = "ioctl", SetLastError = true)]
    private static partial int Ioctl(int fd, nuint request, [Out] byte[] argument);
}
