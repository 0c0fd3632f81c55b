using System.Diagnostics;
using RobotControl.Bus.Tests.Support;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Bus.Tests.Transports;

/// <summary>The SerialPort-based serial link on a pseudo-terminal: the host end is the pty slave, the test plays the bus on the master.</summary>
public sealed class SerialLinkTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(2);

    [Fact]
    public void Bytes_go_both_ways()
    {
        using var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 1_000_000);
        var rx = new byte[16];

        link.Write([0xFF, 0xFF, 0xFD, 0x00, 0x01]);
        ReadExactly(pty, rx, 5);
        Assert.Equal(new byte[] { 0xFF, 0xFF, 0xFD, 0x00, 0x01 }, rx[..5]);

        pty.Write([1, 2, 3]);
        ReadExactly(link, rx, 3);
        Assert.Equal(new byte[] { 1, 2, 3 }, rx[..3]);
        Assert.Contains(pty.SlavePath, link.Description, StringComparison.Ordinal);
        Assert.Equal(1_000_000, link.BaudRate);
    }

    [Fact]
    public void A_read_times_out_with_0_after_sleeping_the_timeout()
    {
        using var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 1_000_000);
        var rx = new byte[16];

        var cpu = ThreadCpu.Now();
        var wall = Stopwatch.StartNew();
        var n = link.Read(rx, TimeSpan.FromMilliseconds(300));
        wall.Stop();
        cpu = ThreadCpu.Now() - cpu;

        Assert.Equal(0, n);
        Assert.InRange(wall.Elapsed, TimeSpan.FromMilliseconds(290), TimeSpan.FromSeconds(5));
        Assert.True(cpu < TimeSpan.FromMilliseconds(30), $"waiting 300 ms used {cpu.TotalMilliseconds:F1} ms of CPU");
    }

    [Fact]
    public void Steady_state_write_read_and_timeout_allocate_nothing()
    {
        using var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 1_000_000);
        var request = new byte[] { 0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x07, 0x00, 0x02 };
        var reply = new byte[] { 0xFF, 0xFF, 0xFD, 0x00, 0x01, 0x04, 0x00, 0x55, 0x00, 0x0A, 0x0B };
        var rx = new byte[64];
        var failures = 0;
        for (var i = 0; i < 50; i++)
        {
            failures += Exchange(pty, link, request, reply, rx);
        }

        var before = GC.GetAllocatedBytesForCurrentThread();
        for (var i = 0; i < 200; i++)
        {
            failures += Exchange(pty, link, request, reply, rx);
        }

        var allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Assert.Equal(0, failures);
        Assert.Equal(0, allocated);
    }

    [Fact]
    public void DiscardInput_drops_what_has_arrived()
    {
        using var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 1_000_000);
        pty.Write([9, 9, 9]);
        Thread.Sleep(50); // the pty hands bytes over asynchronously

        link.DiscardInput();

        Assert.Equal(0, link.Read(new byte[8], TimeSpan.FromMilliseconds(20)));
    }

    [Fact]
    public void A_non_standard_rate_is_set_through_termios2()
    {
        using var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 250_000);

        Assert.Equal(250_000u, pty.SlaveOutputSpeed());
    }

    [Fact]
    public void Rts_driver_enable_on_a_pty_says_the_line_is_missing()
    {
        using var pty = PseudoTerminal.Create();
        var ex = Assert.Throws<IOException>(() => LinkFactory.Open($"serial:{pty.SlavePath}?rs485=rts"));
        Assert.Contains(pty.SlavePath, ex.Message, StringComparison.Ordinal);
        Assert.Contains("rs485=rts", ex.Message, StringComparison.Ordinal);
        Assert.Contains("rs485=auto", ex.Message, StringComparison.Ordinal);

        using var link = LinkFactory.Open($"serial:{pty.SlavePath}?rs485=auto");
        Assert.IsType<SerialLink>(link);
    }

    [Fact]
    public void Settings_the_device_refuses_are_named()
    {
        // SerialPort's own message for refused termios settings says nothing about them.
        var ex = SerialLink.OpenError("/dev/ttyUSB0", "1000000 baud, 8E1", new ArgumentException("Value does not fall within the expected range."));
        Assert.Contains("/dev/ttyUSB0", ex.Message, StringComparison.Ordinal);
        Assert.Contains("refused 1000000 baud, 8E1", ex.Message, StringComparison.Ordinal);
        Assert.Contains("standard rates (e.g. 1000000, 2000000, 3000000, 4000000 baud)", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_missing_device_is_named()
    {
        var ex = Assert.Throws<IOException>(() => LinkFactory.Open("serial:/dev/ttyNOSUCH7?baud=1000000"));
        Assert.Contains("/dev/ttyNOSUCH7: no such device", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void A_file_that_is_no_terminal_is_named()
    {
        var file = Path.GetTempFileName();
        try
        {
            var ex = Assert.Throws<IOException>(() => SerialLink.Open(file, 1_000_000));
            Assert.Contains(file, ex.Message, StringComparison.Ordinal);
            Assert.Contains("not a terminal device", ex.Message, StringComparison.Ordinal);
        }
        finally
        {
            File.Delete(file);
        }
    }

    [Fact]
    public void A_hung_up_pty_fails_the_read()
    {
        var pty = PseudoTerminal.Create();
        using var link = SerialLink.Open(pty.SlavePath, 1_000_000);
        pty.Dispose();

        var ex = Assert.Throws<IOException>(() => link.Read(new byte[8], TimeSpan.FromSeconds(1)));
        Assert.Contains(pty.SlavePath, ex.Message, StringComparison.Ordinal);
    }

    /// <summary>One request/reply turn plus a timed-out read; returns 1 when something came back wrong (no Assert inside: it may allocate).</summary>
    private static int Exchange(PseudoTerminal pty, SerialLink link, byte[] request, byte[] reply, byte[] rx)
    {
        link.Write(request);
        var ok = ReadExactly(pty, rx, request.Length) && rx[7] == request[7];
        pty.Write(reply);
        ok &= ReadExactly(link, rx, reply.Length) && rx[10] == reply[10];
        ok &= link.Read(rx, TimeSpan.FromMicroseconds(100)) == 0;
        return ok ? 0 : 1;
    }

    private static bool ReadExactly(IByteLink link, byte[] buffer, int count)
    {
        var got = 0;
        var start = Stopwatch.GetTimestamp();
        while (got < count && Stopwatch.GetElapsedTime(start) < Patience)
        {
            got += link.Read(buffer.AsSpan(got, count - got), TimeSpan.FromMilliseconds(100));
        }

        return got == count;
    }
}
