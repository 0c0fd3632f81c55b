using System.Globalization;
using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// One process owns a bus: an exclusive advisory lock (<c>flock</c>) on the serial device, taken on a descriptor of
/// its own before the port is opened and configured, plus the terminal's exclusive mode (<c>TIOCEXCL</c>) once it is
/// open. TIOCEXCL alone does not hold for root; the flock does. A second process is refused with the owner's PID, read
/// from <c>/proc/locks</c>, before it can change the port's settings or write a byte.
/// </summary>
internal sealed class DeviceLock : IDisposable
{
    private const int EBusy = 16;
    private int _fd;

    private DeviceLock(int fd) => _fd = fd;

    /// <summary>Locks <paramref name="path"/>; null when the device cannot be opened at all (the port's own open then says why).</summary>
    /// <exception cref="IOException">Another process owns the device (the message names it).</exception>
    public static DeviceLock? Acquire(string path)
    {
        var fd = Libc.Open(path, Libc.ORdWr | Libc.ONoCtty | Libc.ONonBlock | Libc.OCloExec);
        if (fd < 0)
        {
            return Marshal.GetLastPInvokeError() == EBusy ? throw InUse(path) : null;
        }

        if (Libc.Flock(fd, Libc.LockExclusive | Libc.LockNonBlocking) != 0)
        {
            var errno = Marshal.GetLastPInvokeError();
            Libc.Close(fd);
            throw errno == Libc.EWouldBlock ? InUse(path) : Libc.Error($"flock of serial {path}");
        }

        return new DeviceLock(fd);
    }

    /// <summary>Puts the open terminal into exclusive mode: further opens fail (except for root, whom the flock stops).</summary>
    public void MakeExclusive() => Libc.Ioctl(_fd, Libc.TiocExcl, 0);

    /// <inheritdoc />
    public void Dispose()
    {
        if (_fd < 0)
        {
            return;
        }

        // Exclusive mode outlives this descriptor while another end (a pty's) is open: clear it for the next owner.
        Libc.Ioctl(_fd, Libc.TiocNxcl, 0);
        Libc.Flock(_fd, Libc.LockUnlock);
        Libc.Close(_fd);
        _fd = -1;
    }

    /// <summary>The refusal: who owns the device, from /proc/locks.</summary>
    internal static IOException InUse(string path)
    {
        var owner = Owner(path);
        return new IOException(owner is { } pid
            ? $"serial {path} is in use by process {pid} ({ProcessName(pid)}); one process owns a bus: stop it first"
            : $"serial {path} is in use by another process (exclusive mode); one process owns a bus: stop it first");
    }

    /// <summary>The PID holding a flock on <paramref name="path"/>, per /proc/locks, or null.</summary>
    internal static int? Owner(string path)
    {
        if (!FileIdentity.TryGet(path, out var id) || !File.Exists("/proc/locks"))
        {
            return null;
        }

        var key = string.Create(CultureInfo.InvariantCulture, $"{id.DeviceMajor:x2}:{id.DeviceMinor:x2}:{id.Inode}");
        foreach (var line in File.ReadLines("/proc/locks"))
        {
            // "1: FLOCK  ADVISORY  WRITE 1234 00:1a:5 0 EOF"; waiting requests carry "->" and hold nothing.
            var parts = line.Split(' ', StringSplitOptions.RemoveEmptyEntries);
            if (parts.Length < 6 || parts[1] == "->" || parts[1] != "FLOCK")
            {
                continue;
            }

            if (string.Equals(parts[5], key, StringComparison.OrdinalIgnoreCase) && int.TryParse(parts[4], NumberStyles.None, CultureInfo.InvariantCulture, out var pid))
            {
                return pid;
            }
        }

        return null;
    }

    private static string ProcessName(int pid)
    {
        try
        {
            return File.ReadAllText($"/proc/{pid}/comm").Trim();
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return "gone";
        }
    }
}
