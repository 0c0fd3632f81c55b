namespace RobotControl.Cli.Tests.Commands.WebConsole;

/// <summary><c>robotctl console --bring-up</c> refuses bad input with one line and exit 2, before serving anything.</summary>
public sealed class ConsoleBringUpTests : IDisposable
{
    private readonly string _units = Directory.CreateTempSubdirectory("rc-units-").FullName;

    private static string Robot => Cli.RepoFile("hardware/robots/lb-1.0.json");

    public void Dispose() => Directory.Delete(_units, recursive: true);

    [Fact]
    public void Bad_input_is_one_line_and_exit_2()
    {
        Refused(["--transport", "serial:/dev/null"], "--bring-up: give --transport serial:<port> (the box of boards) and --unit <name>");
        Refused(["--unit", "lb-0501"], "--bring-up: give --transport serial:<port> (the box of boards) and --unit <name>");
        Refused(["--transport", "virtual:" + Robot, "--unit", "lb-0501"], "--transport virtual: a virtual robot starts commissioned; serve a box of boards with robotctl bus-sim --pty --factory");
        Refused(["--transport", "serial:/dev/rc-no-such-port", "--unit", "lb-0501"], "/dev/rc-no-such-port");
        Refused(["--transport", "serial:/dev/null", "--unit", "a/b"], "--unit 'a/b': a unit name is a file name (no path separator)");
        File.WriteAllText(Path.Combine(_units, "lb-0502.json"), "{ not json");
        Refused(["--transport", "serial:/dev/null", "--unit", "lb-0502"], $"{Path.Combine(_units, "lb-0502.json")}: not a unit file");

        var both = Cli.Run("console", Cli.RepoFile("graphs/teleop-lb.json"), "--bring-up", Robot, "--transport", "serial:/dev/null", "--unit", "lb-0501", "--units", _units);
        Cli.AssertRefused(both, "console: give a graph file or --bring-up, not both");
        var missing = Cli.Run("console", "--bring-up", Path.Combine(_units, "none.json"), "--transport", "serial:/dev/null", "--unit", "lb-0501", "--units", _units);
        Cli.AssertRefused(missing, "none.json: no such robot file");
        Assert.Equal(2, missing.Code);
    }

    private void Refused(string[] options, string expected)
    {
        var result = Cli.Run(["console", "--bring-up", Robot, "--units", _units, "--bind", "127.0.0.1:0", .. options]);
        Cli.AssertRefused(result, expected);
        Assert.Equal(2, result.Code);
    }
}
