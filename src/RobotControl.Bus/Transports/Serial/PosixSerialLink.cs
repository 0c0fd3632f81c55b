using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// A serial device (USB-RS485 adapter, pty) opened through POSIX calls: raw 8-bit mode at any baud (termios2
/// BOTHER), optional parity, optional kernel-driven RS-485 driver-enable (TIOCSRS485), poll-based reads.
/// </summary>
public sealed unsafe class PosixSerialLink : IByteLink
{
    // termios flag bits (octal in the C headers).
    private const uint IgnBrk = 0x1, BrkInt = 0x2, ParMrk = 0x8, InPck = 0x10, IStrip = 0x20, InlCr = 0x40, IgnCr = 0x80, ICrNl = 0x100, IXon = 0x400, IXAny = 0x800, IXoff = 0x1000;
    private const uint OPost = 0x1;
    private const uint ISig = 0x1, ICanon = 0x2, Echo = 0x8, EchoE = 0x10, EchoNl = 0x40, IExten = 0x8000;
    private const uint CSize = 0x30, Cs8 = 0x30, CStopB = 0x40, CRead = 0x80, ParEnb = 0x100, ParOdd = 0x200, HupCl = 0x400, CLocal = 0x800, CBaud = 0x100F, BOther = 0x1000, CrtsCts = 0x80000000;
    private const int VTime = 5, VMin = 6;

    private int _fd;

    private PosixSerialLink(int fd, string path, int baud)
    {
        _fd = fd;
        Description = $"serial {path} at {baud} baud";
        BaudRate = baud;
    }

    /// <inheritdoc />
    public string Description { get; }

    /// <inheritdoc />
    public int BaudRate { get; }

    /// <summary>Opens <paramref name="path"/> in raw mode at <paramref name="baud"/>.</summary>
    /// <exception cref="IOException">The device cannot be opened or configured.</exception>
    public static PosixSerialLink Open(string path, int baud, SerialParity parity = SerialParity.None, bool rs485 = false)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        ArgumentOutOfRangeException.ThrowIfLessThan(baud, 1);
        var fd = Libc.Open(path, Libc.ORdWr | Libc.ONoCtty | Libc.ONonBlock | Libc.OCloExec);
        if (fd < 0)
        {
            throw Libc.Error($"open {path}");
        }

        try
        {
            ConfigureRaw(fd, baud, parity);
            if (rs485)
            {
                var conf = new Libc.SerialRs485 { Flags = 0x1 | 0x2 }; // enabled, RTS high while sending
                if (Libc.Ioctl(fd, Libc.TiocSRs485, &conf) != 0)
                {
                    throw Libc.Error($"TIOCSRS485 on {path} (the adapter may switch direction itself; omit rs485=true)");
                }
            }

            Libc.Ioctl(fd, Libc.TcFlsh, 2); // TCIOFLUSH: start with empty queues
            return new PosixSerialLink(fd, path, baud);
        }
        catch
        {
            Libc.Close(fd);
            throw;
        }
    }

    /// <summary>Puts an open terminal into raw 8-bit mode with non-blocking reads.</summary>
    internal static void ConfigureRaw(int fd, int baud, SerialParity parity)
    {
        Libc.Termios2 t;
        if (Libc.Ioctl(fd, Libc.TcGets2, &t) != 0)
        {
            throw Libc.Error("TCGETS2");
        }

        t.IFlag &= ~(IgnBrk | BrkInt | ParMrk | IStrip | InlCr | IgnCr | ICrNl | IXon | IXoff | IXAny | InPck);
        t.OFlag &= ~OPost;
        t.LFlag &= ~(Echo | EchoE | EchoNl | ICanon | ISig | IExten);
        t.CFlag &= ~(CSize | ParEnb | ParOdd | CStopB | CrtsCts | CBaud | HupCl);
        t.CFlag |= Cs8 | CRead | CLocal | BOther;
        if (parity != SerialParity.None)
        {
            t.CFlag |= ParEnb | (parity == SerialParity.Odd ? ParOdd : 0);
            t.IFlag |= InPck;
        }

        t.ISpeed = (uint)baud;
        t.OSpeed = (uint)baud;
        t.Cc[VMin] = 0;
        t.Cc[VTime] = 0;
        if (Libc.Ioctl(fd, Libc.TcSets2, &t) != 0)
        {
            throw Libc.Error($"TCSETS2 ({baud} baud)");
        }
    }

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data)
    {
        ObjectDisposedException.ThrowIf(_fd < 0, this);
        fixed (byte* p = data)
        {
            var done = 0;
            while (done < data.Length)
            {
                var n = Libc.Write(_fd, p + done, data.Length - done);
                if (n > 0)
                {
                    done += (int)n;
                    continue;
                }

                var errno = Marshal.GetLastPInvokeError();
                if (n < 0 && errno != Libc.EAgain && errno != Libc.EIntr)
                {
                    throw Libc.Error($"write to {Description}");
                }

                Libc.Poll(_fd, Libc.PollOut, TimeSpan.FromMilliseconds(100));
            }
        }
    }

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        ObjectDisposedException.ThrowIf(_fd < 0, this);
        if (buffer.IsEmpty)
        {
            return 0;
        }

        var events = Libc.Poll(_fd, Libc.PollIn, timeout);
        if (events == 0)
        {
            return 0;
        }

        fixed (byte* p = buffer)
        {
            var n = Libc.Read(_fd, p, buffer.Length);
            if (n >= 0)
            {
                return (int)n;
            }

            var errno = Marshal.GetLastPInvokeError();
            if (errno is Libc.EAgain or Libc.EIntr)
            {
                return 0;
            }

            throw Libc.Error($"read from {Description}");
        }
    }

    /// <inheritdoc />
    public void DiscardInput()
    {
        if (_fd >= 0)
        {
            Libc.Ioctl(_fd, Libc.TcFlsh, 0); // TCIFLUSH
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        var fd = Interlocked.Exchange(ref _fd, -1);
        if (fd >= 0)
        {
            Libc.Close(fd);
        }
    }
}
