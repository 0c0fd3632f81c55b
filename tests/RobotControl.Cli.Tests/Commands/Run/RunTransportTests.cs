using RobotControl.Cli.Commands.Run;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary><c>run --transport</c>: bad values are refused in one line before anything is loaded or opened.</summary>
[Collection(RunProcess.Collection)]
public sealed class RunTransportTests
{
    private static (int Code, string Output, string Error) Run(string transport, bool isVirtual = false)
    {
        var output = new StringWriter();
        var error = new StringWriter();
        var code = RunCommand.Run(RunProcess.Graph, isVirtual, TimeSpan.FromSeconds(1), null, null, null, 1, [], new RunExtras(transport, false), output, error);
        return (code, output.ToString(), error.ToString());
    }

    [Fact]
    public void An_unknown_scheme_is_one_line_naming_the_option_and_nothing_starts()
    {
        var (code, output, error) = Run("rs232:/dev/ttyS0");
        Assert.Equal(2, code);
        Assert.Equal(string.Empty, output); // the run never began
        Assert.Single(error.TrimEnd().Split('\n'));
        Assert.StartsWith("--transport:", error, StringComparison.Ordinal);
        Assert.Contains("unknown kind 'rs232'", error, StringComparison.Ordinal);
    }

    [Fact]
    public void A_missing_device_is_one_line_naming_it_and_nothing_starts()
    {
        var (code, output, error) = Run("serial:/dev/robotcontrol-no-such-tty?baud=1000000");
        Assert.Equal(2, code);
        Assert.Equal(string.Empty, output);
        Assert.Equal("--transport serial:/dev/robotcontrol-no-such-tty?baud=1000000: no device /dev/robotcontrol-no-such-tty", error.TrimEnd());
    }

    [Fact]
    public void A_real_transport_and_virtual_contradict()
    {
        var (code, output, error) = Run("serial:/dev/null", isVirtual: true);
        Assert.Equal(2, code);
        Assert.Equal(string.Empty, output);
        Assert.Contains("--virtual", error, StringComparison.Ordinal);
    }

    [Fact]
    public void A_virtual_transport_runs_the_virtual_robot()
    {
        var (code, output, error) = Run("virtual");
        Assert.True(code == 0, error);
        Assert.Contains("virtual robot", output, StringComparison.Ordinal);
        Assert.Contains("stop: torque off on all 6 modules (read back)", output, StringComparison.Ordinal);
    }
}
