using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// A pseudo-terminal pair made with posix_openpt/grantpt/unlockpt/ptsname: the master end (this object's
/// <see cref="IByteLink"/>) plays the bus; programs open <see cref="SlavePath"/> as if it were a serial adapter.
/// The slave end is held open (in raw mode) so the master keeps working while clients come and go.
/// </summary>
public sealed unsafe class PseudoTerminal : IByteLink
{
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

            PosixSerialLink.ConfigureRaw(slave, LinkUri.DefaultBaud, SerialParity.None);
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
        fixed (byte* p = data)
        {
            var done = 0;
            while (done < data.Length)
            {
                var n = Libc.Write(_master, p + done, data.Length - done);
                if (n <= 0)
                {
                    var errno = Marshal.GetLastPInvokeError();
                    if (errno is not (Libc.EAgain or Libc.EIntr))
                    {
                        throw Libc.Error("write to pty master");
                    }

                    Libc.Poll(_master, Libc.PollOut, TimeSpan.FromMilliseconds(10));
                    continue;
                }

                done += (int)n;
            }
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

        fixed (byte* p = buffer)
        {
            var n = Libc.Read(_master, p, buffer.Length);
            return n > 0 ? (int)n : 0;
        }
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
}
