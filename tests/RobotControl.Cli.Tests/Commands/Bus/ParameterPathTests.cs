using System.Globalization;
using RobotControl.Definitions.Loading;
using RobotControl.Modules;
using RobotControl.Plugins.Standard.Conditioning;
using RobotControl.Plugins.Touch;
using RobotControl.Runtime.Discovery;
using RobotControl.WebConsole.Adapter;
using RobotControl.WebConsole.Session;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>
/// <c>robotctl params set</c> and the console's parameter edit take the one parameter path: a value the command line
/// refuses, the console refuses with the same rule text (each prefixed by who asked).
/// </summary>
public sealed class ParameterPathTests
{
    [Theory]
    [InlineData("current_limit", 5000)]
    [InlineData("kp", 70000)]
    public async Task A_value_the_command_line_refuses_the_console_refuses_with_the_same_rule(string field, long counts)
    {
        // right.elbow is module 2, motor 0: the console is given the same counts in the robot's units.
        var robotFile = Cli.RepoFile("hardware/robots/lb-1.0.json");
        var robot = RobotLoader.Load(robotFile);
        var module = robot.Modules.Modules.Single(m => m.Id == 2);
        var elbow = new MotorConfig(robot, module, module.Motors.Single(m => m.Channel == 0));
        Assert.Equal("right.elbow", elbow.FullName);
        var value = MotorParameter.Find(field)!.FromCounts(elbow, counts);

        var cli = Cli.Run("params", "set", "virtual:" + robotFile, "--module", "2", "--field", field, "--motor", "0", "--value", counts.ToString(CultureInfo.InvariantCulture));
        Cli.AssertRefused(cli, $"{field} = {counts} is outside its range 0..");
        var rule = cli.Error.Trim(); // the command line prints the rule as it is
        Assert.StartsWith($"{field} = {counts} is outside its range 0..", rule, StringComparison.Ordinal);
        Assert.EndsWith("; nothing was written", rule, StringComparison.Ordinal);

        using var session = new LiveSession(new LiveSessionOptions
        {
            GraphPath = Cli.RepoFile("graphs/teleop-lb.json"),
            Catalog = PluginCatalog.FromAssemblies(typeof(ClutchPlugin).Assembly, typeof(TouchPlugin).Assembly),
            Virtual = true,
        });
        Assert.True((await session.TorqueAsync(false)).Succeeded);
        var console = await session.WriteParameterAsync("right.elbow", field, value);

        Assert.Equal(CommandOutcome.BadInput, console.Outcome);
        Assert.StartsWith("right.elbow: ", console.Message, StringComparison.Ordinal);
        Assert.EndsWith($"): {rule}", console.Message, StringComparison.Ordinal);
    }
}
