using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Bus.Tests.Transports;

/// <summary>One process owns a serial bus: flock plus TIOCEXCL on a pty pair (holds for root too).</summary>
public sealed class DeviceLockTests
{
    [Fact]
    public void A_second_open_is_refused_with_the_owner_pid_until_the_first_closes()
    {
        using var pty = PseudoTerminal.Create();
        using (SerialLink.Open(pty.SlavePath, 1_000_000))
        {
            var ex = Assert.Throws<IOException>(() => SerialLink.Open(pty.SlavePath, 1_000_000));

            Assert.Contains($"in use by process {Environment.ProcessId}", ex.Message, StringComparison.Ordinal);
            Assert.Equal(Environment.ProcessId, DeviceLock.Owner(pty.SlavePath));
        }

        using var again = SerialLink.Open(pty.SlavePath, 1_000_000);
        Assert.Null(DeviceLock.Owner("/dev/null"));
    }
}
