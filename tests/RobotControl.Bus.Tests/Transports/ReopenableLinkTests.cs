using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Bus.Tests.Transports;

/// <summary><see cref="ReopenableLink"/> on a pty: the device released while another open visits it at another baud, then opened again at its own, also after a failure.</summary>
public sealed class ReopenableLinkTests
{
    [Fact]
    public void Released_frees_the_device_for_another_baud_and_opens_it_again_at_its_own()
    {
        using var pty = PseudoTerminal.Create();
        using var link = new ReopenableLink(() => SerialLink.Open(pty.SlavePath, 1_000_000));

        var visited = link.Released(() =>
        {
            using var other = SerialLink.Open(pty.SlavePath, 2_000_000); // refused while the link holds the device
            return pty.ClientBaud;
        });

        Assert.Equal(2_000_000, visited);
        Assert.Equal(1_000_000, pty.ClientBaud);
        AssertCarries(link, pty);

        Assert.Throws<IOException>(() => link.Released<int>(() => throw new IOException("nothing answers")));
        Assert.Equal(1_000_000, pty.ClientBaud);
        AssertCarries(link, pty);
        Assert.Throws<IOException>(() => SerialLink.Open(pty.SlavePath, 1_000_000)); // held again
    }

    private static void AssertCarries(ReopenableLink link, PseudoTerminal pty)
    {
        link.Write([0xFF, 0xFD]);
        var buffer = new byte[8];
        var n = 0;
        while (n < 2 && pty.Read(buffer.AsSpan(n), TimeSpan.FromSeconds(2)) is var got and > 0)
        {
            n += got;
        }

        Assert.Equal(new byte[] { 0xFF, 0xFD }, buffer[..n]);
    }
}
