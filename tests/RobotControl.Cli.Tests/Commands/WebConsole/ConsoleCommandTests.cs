using RobotControl.Cli.Commands.WebConsole;

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

    [Fact]
    public void A_short_token_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--token", "short"), "--token: give at least 8 characters");

    [Fact]
    public void A_key_without_a_certificate_is_refused() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--https-key", "console.key"), "--https-key: give --https-cert too");

    [Fact]
    public void A_certificate_file_that_is_not_there_is_refused_with_one_line() =>
        Cli.AssertRefused(Cli.Run("console", Graph, "--virtual", "--https-cert", "/nonexistent/console.pfx"), "--https-cert '/nonexistent/console.pfx': no such file");

    [Fact]
    public void Plain_http_off_this_host_is_warned_of_in_one_line_and_loopback_or_https_is_not()
    {
        var offHost = new ConsoleAccess("0.0.0.0:5080", null, [], null, null).Options();
        Assert.Equal("console: warning: plain HTTP on 0.0.0.0:5080, off this host: the token and every command cross the network unencrypted; give --https-cert", ConsoleAccess.Warning(offHost));
        Assert.Null(ConsoleAccess.Warning(new ConsoleAccess("127.0.0.1:5080", null, [], null, null).Options()));
    }
}
