namespace RobotControl.Cli.Tests.Commands.WebConsole;

/// <summary><c>robotctl console</c>'s surgeon-station options refuse bad input with one line, before serving anything.</summary>
public sealed class ConsoleCommandTests
{
    private static string Graph => Cli.RepoFile("graphs/teleop-lb.json");

    [Fact]
    public void An_unknown_page_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--page", "theatre"), "--page 'theatre': no such page (pages: bus, plots, view3d, status, editor, surgeon)");

    [Fact]
    public void A_fault_form_the_console_does_not_inject_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--inject", "stuck=right.elbow@5s"), "the console injects silent=<module>@<time> only");

    [Fact]
    public void A_fault_on_a_real_bus_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--transport", "tcp:127.0.0.1:9", "--inject", "silent=left.forearm@5s"), "faults are injected into the virtual robot only");

    [Fact]
    public void A_silent_module_that_does_not_exist_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--inject", "silent=left.knee@5s"), "no module 'left.knee'");
}
