using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>The few libc calls a POSIX serial port needs (System.IO.Ports is not available here).</summary>
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
    public const int EIo = 5;
    public const int EAgain = 11;

    // ioctl requests (asm-generic, x86-64 and arm64 alike).
    public const uint TcGets2 = 0x802C542A;
    public const uint TcSets2 = 0x402C542B;
    public const uint TcFlsh = 0x540B;
    public const uint TiocSRs485 = 0x542F;

    [LibraryImport("libc", EntryPoint = "open", SetLastError = true, StringMarshalling = StringMarshalling.Utf8)]
    public static partial int Open(string path, int flags);

    [LibraryImport("libc", EntryPoint = "close", SetLastError = true)]
    public static partial int Close(int fd);

    [LibraryImport("libc", EntryPoint = "read", SetLastError = true)]
    public static partial nint Read(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "write", SetLastError = true)]
    public static partial nint Write(int fd, byte* buffer, nint count);

    [LibraryImport("libc", EntryPoint = "ppoll", SetLastError = true)]
    public static partial int PPoll(PollFd* fds, nuint count, TimeSpec* timeout, void* sigmask);

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

    /// <summary>Waits until <paramref name="fd"/> has <paramref name="events"/> or the timeout passes; returns revents (0 on timeout).</summary>
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

    [StructLayout(LayoutKind.Sequential)]
    public struct PollFd
    {
        public int Fd;
        public short Events;
        public short REvents;
    }

    [StructLayout(LayoutKind.Sequential)]
    public struct TimeSpec
    {
        public long Seconds;
        public long Nanoseconds;
    }

    /// <summary>Kernel <c>struct termios2</c> (arbitrary baud through BOTHER).</summary>
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

    /// <summary>Kernel <c>struct serial_rs485</c>.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SerialRs485
    {
        public uint Flags;
        public uint DelayRtsBeforeSend;
        public uint DelayRtsAfterSend;
        public fixed uint Padding[5];
    }
}
