using RobotControl.Cli.Tests.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary><c>robotctl bus-sim</c>: the baud it commissions its modules at, and how it stops.</summary>
[Collection(RunProcess.Collection)]
public sealed class BusSimCommandTests
{
    private static readonly TimeSpan Patience = TimeSpan.FromSeconds(60);

    private static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    [Fact]
    public void A_baud_the_modules_cannot_be_set_to_is_refused_with_the_rates_they_can()
    {
        var result = Cli.Run("bus-sim", Robot, "--pty", "--baud", "123");
        Cli.AssertRefused(result, "--baud 123: not a rate the modules support (");
        Assert.Contains("3000000", result.Error, StringComparison.Ordinal);
    }

    [Fact]
    public void Baud_commissions_the_modules_at_that_rate_and_the_transport_says_so()
    {
        var (code, output, error) = Cli.Run("bus-sim", Robot, "--pty", "--baud", "3000000", "--seconds", "0.5");
        Assert.True(code == 0, error);
        Assert.Contains("?baud=3000000", output, StringComparison.Ordinal);
        Assert.Contains("stopped after", output, StringComparison.Ordinal);
    }

    [Fact]
    public void SIGTERM_stops_serving_and_says_how_far_the_simulation_fell_behind()
    {
        using var sim = new RunProcess("bus-sim", Robot, "--pty");
        sim.WaitFor("serving", Patience);
        sim.Signal("TERM");
        Assert.Equal(0, sim.WaitForExit(Patience));
        Assert.Matches(@"stopped after [0-9.]+ s simulated: \d+ ms slipped behind real time, longest stall [0-9.]+ ms at [0-9.]+ s \(process CPU in it [0-9.]+ ms\), compiled while serving \d+ methods \([0-9.]+ ms\), \d+ collections", sim.Output);
    }
}
