using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// A pseudo-terminal pair made with posix_openpt/grantpt/unlockpt/ptsname: the master end (this object's
/// <see cref="IByteLink"/>) plays the bus; programs open <see cref="SlavePath"/> as if it were a serial adapter.
/// The slave end is held open (in raw mode) so the master keeps working while clients come and go. This is the
/// simulator's side of a virtual bus; hosts open the slave through <see cref="SerialLink"/> like any serial device.
/// </summary>
public sealed unsafe class PseudoTerminal : IByteLink
{
    // termios flag bits (octal in the C headers).
    private const uint CSize = 0x30, Cs8 = 0x30, CRead = 0x80, ParEnb = 0x100, CLocal = 0x800;
    private const int VTime = 5, VMin = 6;

    private int _master;
    private int _slave;

    private PseudoTerminal(int master, int slave, string slavePath)
    {
        _master = master;
        _slave = slave;
        SlavePath = slavePath;
    }

    /// <summary>Path of the slave end, e.g. <c>/dev/pts/3</c>.</summary>
    public string SlavePath { get; }

    /// <inheritdoc />
    public string Description => $"pty master of {SlavePath}";

    /// <inheritdoc />
    public int BaudRate => LinkUri.DefaultBaud;

    /// <summary>Creates a pty pair.</summary>
    /// <exception cref="IOException">The system refuses a pty.</exception>
    public static PseudoTerminal Create()
    {
        var master = Libc.PosixOpenpt(Libc.ORdWr | Libc.ONoCtty);
        if (master < 0)
        {
            throw Libc.Error("posix_openpt");
        }

        try
        {
            if (Libc.Grantpt(master) != 0 || Libc.Unlockpt(master) != 0)
            {
                throw Libc.Error("grantpt/unlockpt");
            }

            var name = stackalloc byte[128];
            if (Libc.PtsnameR(master, name, 128) != 0)
            {
                throw Libc.Error("ptsname_r");
            }

            var path = Marshal.PtrToStringUTF8((nint)name) ?? throw new IOException("ptsname returned nothing");
            var slave = Libc.Open(path, Libc.ORdWr | Libc.ONoCtty | Libc.OCloExec | Libc.ONonBlock);
            if (slave < 0)
            {
                throw Libc.Error($"open {path}");
            }

            try
            {
                MakeRaw(slave, path);
            }
            catch
            {
                Libc.Close(slave);
                throw;
            }

            return new PseudoTerminal(master, slave, path);
        }
        catch
        {
            Libc.Close(master);
            throw;
        }
    }

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data)
    {
        while (!data.IsEmpty)
        {
            var n = Libc.Write(_master, data);
            if (n > 0)
            {
                data = data[n..];
                continue;
            }

            if (Marshal.GetLastPInvokeError() is not (Libc.EAgain or Libc.EIntr))
            {
                throw Libc.Error($"write to the pty master of {SlavePath}");
            }

            Libc.Poll(_master, Libc.PollOut, TimeSpan.FromMilliseconds(10));
        }
    }

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        var events = Libc.Poll(_master, Libc.PollIn, timeout);
        if ((events & Libc.PollIn) == 0)
        {
            return 0;
        }

        return Math.Max(0, Libc.Read(_master, buffer));
    }

    /// <inheritdoc />
    public void DiscardInput() => Libc.Ioctl(_master, Libc.TcFlsh, 0);

    /// <inheritdoc />
    public void Dispose()
    {
        var slave = Interlocked.Exchange(ref _slave, -1);
        if (slave >= 0)
        {
            Libc.Close(slave);
        }

        var master = Interlocked.Exchange(ref _master, -1);
        if (master >= 0)
        {
            Libc.Close(master);
        }
    }

    /// <summary>
    /// The baud the client set on its end of the pty: what a real line would run at. A simulator serving the pty follows
    /// it (only modules at that baud hear and are heard).
    /// </summary>
    public int ClientBaud => (int)SlaveOutputSpeed();

    /// <summary>
    /// The output speed the client last set on the slave (termios2 <c>c_ospeed</c>), read through the slave end this
    /// object holds: the client's port may be exclusive (TIOCEXCL), so a second open could fail.
    /// </summary>
    internal uint SlaveOutputSpeed()
    {
        Libc.Termios2 t;
        return Libc.Ioctl(_slave, Libc.TcGets2, &t) == 0 ? t.OSpeed : throw Libc.Error($"TCGETS2 on {SlavePath}");
    }

    /// <summary>Raw 8-bit mode, no echo, non-blocking reads: until a client configures the slave, nothing may be echoed back to the bus.</summary>
    private static void MakeRaw(int fd, string path)
    {
        Libc.Termios2 t;
        if (Libc.Ioctl(fd, Libc.TcGets2, &t) != 0)
        {
            throw Libc.Error($"TCGETS2 on {path}");
        }

        t.IFlag = 0;
        t.OFlag = 0;
        t.LFlag = 0;
        t.CFlag = (t.CFlag & ~(CSize | ParEnb)) | Cs8 | CRead | CLocal;
        t.Cc[VMin] = 0;
        t.Cc[VTime] = 0;
        if (Libc.Ioctl(fd, Libc.TcSets2, &t) != 0)
        {
            throw Libc.Error($"TCSETS2 on {path}");
        }
    }
}
