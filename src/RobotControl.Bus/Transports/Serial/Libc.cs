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

    public static IOException Error(string what) =>
        new($"{what} failed: {Marshal.GetPInvokeErrorMessage(Marshal.GetLastPInvokeError())} (errno {Marshal.GetLastPInvokeError()})");

    [LibraryImport("libc", EntryPoint = "read", SetLastError = true)]
    private static partial nint ReadCore(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "write", SetLastError = true)]
    private static partial nint WriteCore(int fd, byte* buffer, nint count);

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
