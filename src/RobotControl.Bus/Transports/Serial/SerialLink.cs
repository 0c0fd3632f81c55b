using System.IO.Ports;
using System.Runtime.InteropServices;

namespace RobotControl.Bus.Transports.Serial;

/// <summary>
/// A serial device (USB-RS485 adapter, on-board UART, pseudo-terminal) opened and configured by
/// <see cref="SerialPort"/>: 8 data bits, the transport's parity, 1 stop bit, no handshake, DTR and RTS low. With
/// <see cref="Rs485DriverEnable.Rts"/> it asserts RTS around each write for transceivers whose driver-enable hangs on
/// RTS. Bytes move by poll/read/write on the port's own descriptor (see <see cref="SerialPortDescriptor"/>): a read
/// sleeps in the kernel until a byte arrives or the timeout passes, returns 0 on timeout and allocates nothing.
/// </summary>
public sealed class SerialLink : IByteLink
{
    // A write that finds the output queue full waits for room this long before it declares the device stuck.
    private static readonly TimeSpan WriteStall = TimeSpan.FromSeconds(1);

    private readonly SerialPort _port;
    private readonly SafeHandle _handle;
    private readonly int _fd;
    private readonly Rs485DriverEnable _driverEnable;
    private readonly DeviceLock? _lock;
    private bool _disposed;

    private SerialLink(SerialPort port, SafeHandle handle, string description, int baud, Rs485DriverEnable driverEnable, DeviceLock? deviceLock)
    {
        _port = port;
        _lock = deviceLock;
        _handle = handle;
        _fd = (int)handle.DangerousGetHandle();
        _driverEnable = driverEnable;
        Description = description;
        BaudRate = baud;
    }

    /// <inheritdoc />
    public string Description { get; }

    /// <inheritdoc />
    public int BaudRate { get; }

    /// <summary>Opens <paramref name="path"/> at <paramref name="baud"/>, 8 data bits, <paramref name="parity"/>, 1 stop bit.</summary>
    /// <exception cref="IOException">
    /// The device is missing, owned by another process (see <see cref="DeviceLock"/>; the message names its PID), refuses
    /// the settings, or lacks the RTS line <paramref name="driverEnable"/> needs.
    /// </exception>
    /// <exception cref="PlatformNotSupportedException">Not a Unix system.</exception>
    public static SerialLink Open(string path, int baud, SerialParity parity = SerialParity.None, Rs485DriverEnable driverEnable = Rs485DriverEnable.Auto)
    {
        ArgumentException.ThrowIfNullOrEmpty(path);
        ArgumentOutOfRangeException.ThrowIfLessThan(baud, 1);
        if (OperatingSystem.IsWindows() || OperatingSystem.IsBrowser() || OperatingSystem.IsWasi())
        {
            throw new PlatformNotSupportedException($"serial {path}: the serial link moves bytes with poll/read/write and needs Linux or another Unix");
        }

        var frame = $"{baud} baud, 8{parity.ToString()[0]}1";
        var description = $"serial {path} ({frame}" + (driverEnable == Rs485DriverEnable.Rts ? ", RTS driver-enable)" : ")");
        // The lock comes first: a second process must not reconfigure the owner's port.
        var deviceLock = DeviceLock.Acquire(path);
        var port = new SerialPort(path, baud, ToPorts(parity), 8, StopBits.One) { Handshake = Handshake.None, DtrEnable = false, RtsEnable = false };
        try
        {
            port.Open();
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or ArgumentException or InvalidOperationException)
        {
            port.Dispose();
            deviceLock?.Dispose();
            throw OpenError(path, frame, ex);
        }

        try
        {
            deviceLock?.MakeExclusive();
            if (driverEnable == Rs485DriverEnable.Rts)
            {
                SetRts(port, path, false); // probes the line, and the bus starts out listening
            }

            return new SerialLink(port, SerialPortDescriptor.Acquire(port), description, baud, driverEnable, deviceLock);
        }
        catch
        {
            port.Dispose();
            deviceLock?.Dispose();
            throw;
        }
    }

    /// <inheritdoc />
    public void Write(ReadOnlySpan<byte> data)
    {
        ObjectDisposedException.ThrowIf(_disposed, this);
        if (_driverEnable == Rs485DriverEnable.Auto)
        {
            WriteAll(data);
            return;
        }

        _port.RtsEnable = true;
        try
        {
            WriteAll(data);

            // tcdrain: returns when the UART has shifted out the last stop bit, so the driver is not switched off under it.
            _port.BaseStream.Flush();
        }
        finally
        {
            _port.RtsEnable = false; // release the bus for the reply
        }
    }

    /// <inheritdoc />
    public int Read(Span<byte> buffer, TimeSpan timeout)
    {
        ObjectDisposedException.ThrowIf(_disposed, this);
        if (buffer.IsEmpty)
        {
            return 0;
        }

        var events = Libc.Poll(_fd, Libc.PollIn, timeout);
        if (events == 0)
        {
            return 0;
        }

        var n = Libc.Read(_fd, buffer);
        if (n > 0)
        {
            return n;
        }

        if (n < 0 && Marshal.GetLastPInvokeError() is not (Libc.EAgain or Libc.EIntr))
        {
            throw Libc.Error($"read from {Description}");
        }

        if ((events & (Libc.PollHup | Libc.PollErr)) != 0)
        {
            throw new IOException($"{Description}: the device hung up (adapter unplugged, or the other end of the pty closed)");
        }

        return 0;
    }

    /// <inheritdoc />
    public void DiscardInput()
    {
        ObjectDisposedException.ThrowIf(_disposed, this);
        _port.DiscardInBuffer();
    }

    /// <inheritdoc />
    public void Dispose()
    {
        if (_disposed)
        {
            return;
        }

        _disposed = true;
        _handle.DangerousRelease();
        _port.Dispose();
        _lock?.Dispose();
    }

    private void WriteAll(ReadOnlySpan<byte> data)
    {
        while (!data.IsEmpty)
        {
            var n = Libc.Write(_fd, data);
            if (n > 0)
            {
                data = data[n..];
                continue;
            }

            if (n < 0 && Marshal.GetLastPInvokeError() is not (Libc.EAgain or Libc.EIntr))
            {
                throw Libc.Error($"write to {Description}");
            }

            if (Libc.Poll(_fd, Libc.PollOut, WriteStall) == 0)
            {
                throw new IOException($"{Description}: the output queue stayed full for {WriteStall.TotalSeconds:F0} s (nothing takes the bytes)");
            }
        }
    }

    private static void SetRts(SerialPort port, string path, bool asserted)
    {
        try
        {
            port.RtsEnable = asserted;
        }
        catch (IOException ex)
        {
            throw new IOException($"serial {path}: rs485=rts switches the transceiver with the RTS line, but the device has no modem lines ({ex.Message}); a pseudo-terminal never has them. Use rs485=auto (the default) with adapters that switch direction themselves", ex);
        }
    }

    /// <summary>A clear message for what <see cref="SerialPort.Open"/> threw.</summary>
    internal static IOException OpenError(string path, string frame, Exception ex) => ex switch
    {
        // SerialPort reports settings the terminal refused as an ArgumentException without detail.
        ArgumentException => new IOException($"serial {path}: the device refused {frame} ({ex.Message}). The standard rates (e.g. 1000000, 2000000, 3000000, 4000000 baud) work with USB-RS485 adapters, other rates only where the driver can make them; pseudo-terminals carry no parity", ex),

        // SerialPort says "access denied" for a missing path and a non-terminal too.
        UnauthorizedAccessException when !File.Exists(path) => new IOException($"cannot open serial {path}: no such device (is the adapter plugged in? usb:<vendor>:<product>[:<serial>] finds it by ID)", ex),
        UnauthorizedAccessException => new IOException($"cannot open serial {path} ({ex.Message}): it is not a terminal device, this user may not open it (group dialout), or another program holds it", ex),
        _ => new IOException($"cannot open serial {path} ({frame}): {ex.Message}", ex),
    };

    private static Parity ToPorts(SerialParity parity) => parity switch
    {
        SerialParity.Even => Parity.Even,
        SerialParity.Odd => Parity.Odd,
        _ => Parity.None,
    };
}
