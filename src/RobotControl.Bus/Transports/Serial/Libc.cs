using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// The few libc calls left: poll/read/write on a serial port's descriptor (the data path of <see cref="SerialLink"/>,
/// which SerialPort opens and configures) and the pseudo-terminal calls of <see cref="PseudoTerminal"/>.
/// </summary>
internal static unsafe partial class Libc
{
    public const int ORdWr = 0x2;
    public const int ONoCtty = 0x100;
    public const int ONonBlock = 0x800;
    public const int OCloExec = 0x80000;
    public const short PollIn = 0x1;
    public const short PollOut = 0x4;
    public const short PollErr = 0x8;
    public const short PollHup = 0x10;
    public const int EIntr = 4;
    public const int EAgain = 11;

    // ioctl requests (asm-generic, x86-64 and arm64 alike).
    public const uint TcGets2 = 0x802C542A;
    public const uint TcSets2 = 0x402C542B;
    public const uint TcFlsh = 0x540B;

    [LibraryImport("libc", EntryPoint = "open", SetLastError = true, StringMarshalling = StringMarshalling.Utf8)]
    public static partial int Open(string path, int flags);

    [LibraryImport("libc", EntryPoint = "close", SetLastError = true)]
    public static partial int Close(int fd);

    [LibraryImport("libc", EntryPoint = "ioctl", SetLastError = true)]
    public static partial int Ioctl(int fd, nuint request, void* argument);

    [LibraryImport("libc", EntryPoint = "ioctl", SetLastError = true)]
    public static partial int Ioctl(int fd, nuint request, nint argument);

    public const uint TiocExcl = 0x540C;
    public const uint TiocNxcl = 0x540D;
    public const int LockExclusive = 2;
    public const int LockNonBlocking = 4;
    public const int LockUnlock = 8;
    public const int EWouldBlock = EAgain;

    [LibraryImport("libc", EntryPoint = "flock", SetLastError = true)]
    public static partial int Flock(int fd, int operation);

    [LibraryImport("libc", EntryPoint = "posix_openpt", SetLastError = true)]
    public static partial int PosixOpenpt(int flags);

    [LibraryImport("libc", EntryPoint = "grantpt", SetLastError = true)]
    public static partial int Grantpt(int fd);

    [LibraryImport("libc", EntryPoint = "unlockpt", SetLastError = true)]
    public static partial int Unlockpt(int fd);

    [LibraryImport("libc", EntryPoint = "ptsname_r", SetLastError = true)]
    public static partial int PtsnameR(int fd, byte* buffer, nuint length);

    /// <summary>read(2) into <paramref name="buffer"/>; -1 with errno set on failure.</summary>
    public static int Read(int fd, Span<byte> buffer)
    {
        fixed (byte* p = buffer)
        {
            return (int)ReadCore(fd, p, buffer.Length);
        }
    }

    /// <summary>write(2) of <paramref name="data"/>; the count written, or -1 with errno set.</summary>
    public static int Write(int fd, ReadOnlySpan<byte> data)
    {
        fixed (byte* p = data)
        {
            return (int)WriteCore(fd, p, data.Length);
        }
    }

    /// <summary>
    /// Waits until <paramref name="fd"/> has <paramref name="events"/> or the timeout passes (ppoll: sub-millisecond
    /// timeouts, the thread sleeps in the kernel); returns revents (0 on timeout).
    /// </summary>
    public static short Poll(int fd, short events, TimeSpan timeout)
    {
        var pfd = new PollFd { Fd = fd, Events = events };
        var ticks = Math.Max(0, timeout.Ticks);
        var ts = new TimeSpec { Seconds = ticks / TimeSpan.TicksPerSecond, Nanoseconds = ticks % TimeSpan.TicksPerSecond * 100 };
        while (true)
        {
            var r = PPoll(&pfd, 1, &ts, null);
            if (r >= 0)
            {
                return r == 0 ? (short)0 : pfd.REvents;
            }

            if (Marshal.GetLastPInvokeError() != EIntr)
            {
                throw Error("poll");
            }
        }
    }

    /// <summary>statx(2) of <paramref name="path"/> (links followed): 0, or -1 with errno set.</summary>
    public static int Statx(string path, out int mode, out uint deviceMajor, out uint deviceMinor, out ulong inode)
    {
        // struct statx is the same on every architecture: 256 bytes; stx_mode at 28, stx_ino at 32, stx_dev_major/minor at 136/140.
        var buffer = stackalloc byte[256];
        const int AtFdCwd = -100, StatxBasicStats = 0x7FF;
        var r = StatxCore(AtFdCwd, path, 0, StatxBasicStats, buffer);
        mode = r == 0 ? *(ushort*)(buffer + 28) : 0;
        inode = r == 0 ? *(ulong*)(buffer + 32) : 0;
        deviceMajor = r == 0 ? *(uint*)(buffer + 136) : 0;
        deviceMinor = r == 0 ? *(uint*)(buffer + 140) : 0;
        return r;
    }

    public static IOException Error(string what) =>
        new($"{what} failed: {Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError())} (errno {Marshal.GetLastPInvokeError()})");

    [LibraryImport("libc", EntryPoint = "read", SetLastError = true)]
    private static partial nint ReadCore(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "write", SetLastError = true)]
    private static partial nint WriteCore(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "statx", SetLastError = true, StringMarshalling = StringMarshalling.Utf8)]
    private static partial int StatxCore(int dirFd, string path, int flags, uint mask, byte* buffer);

    [LibraryImport("libc", EntryPoint = "ppoll", SetLastError = true)]
    private static partial int PPoll(PollFd* fds, nuint count, TimeSpec* timeout, void* sigmask);

    [StructLayout(LayoutKind.Sequential)]
    private struct PollFd
    {
        public int Fd;
        public short Events;
        public short REvents;
    }

    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    /// <summary>Kernel <c>struct termios2</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct Termios2
    {
        public uint IFlag;
        public uint OFlag;
        public uint CFlag;
        public uint LFlag;
        public byte Line;
        public fixed byte Cc[19];
        public uint ISpeed;
        public uint OSpeed;
    }
}
