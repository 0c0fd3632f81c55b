using RobotControl.Bus.Transports.Serial;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>One process owns a bus (issue 18, class 7): a second open of a serial device in use is refused with the owner's PID.</summary>
[Collection(PtyBus.Collection)]
public sealed class BusOwnershipTests
{
    [Fact]
    public void A_command_on_a_serial_bus_another_link_holds_is_refused_with_the_owner_pid()
    {
        using var bus = new PtyBus();
        using (SerialLink.Open(bus.SlavePath, 1_000_000))
        {
            var result = Cli.Run("discover", bus.Transport);

            Cli.AssertRefused(result, $"in use by process {Environment.ProcessId}");
        }

        // Released with the link: the next command gets the bus.
        var (code, output, error) = Cli.Run("discover", bus.Transport);
        Assert.True(code == 0, error);
        Assert.Contains("6 module(s) answered", output, StringComparison.Ordinal);
    }
}
