namespace RobotControl.Cli.Tests;

/// <summary>The entry path: a bad command line gets its errors in one line each, never the help text or a stack trace (issue 18, class 5).</summary>
public sealed class CliAppTests
{
    [Fact]
    public void An_unknown_option_gets_one_line_and_exit_2()
    {
        var (code, output, error) = Cli.Run("discover", "virtual:x.json", "--bogus");

        Assert.Equal(CliApp.BadInput, code);
        Assert.Equal(string.Empty, output);
        Assert.Contains("--bogus", error, StringComparison.Ordinal);
        Assert.DoesNotContain("Usage", error, StringComparison.Ordinal);
    }

    [Fact]
    public void A_missing_robot_file_is_one_line_not_a_stack_trace() =>
        Cli.AssertRefused(Cli.Run("fk", "/nonexistent/robot.json"), "robot.json");
}
