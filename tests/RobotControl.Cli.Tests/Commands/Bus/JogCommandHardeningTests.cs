using System.Text.Json.Nodes;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary><c>robotctl jog</c> fails when it should (issue 18, classes 3 and 6).</summary>
[Collection(PtyBus.Collection)]
public sealed class JogCommandHardeningTests : IDisposable
{
    private readonly string _root = Path.Combine(Path.GetTempPath(), $"rc-jog-{Guid.NewGuid():N}");

    public JogCommandHardeningTests() => Directory.CreateDirectory(_root);

    [Fact]
    public void A_jog_on_a_bus_that_differs_from_the_robot_file_exits_non_zero()
    {
        // The bus lacks the left forearm module (id 13) that the robot file names.
        using var bus = new PtyBus(simulatedRobotFile: RobotWithout(13));

        var (code, output, error) = bus.Run("jog", "--motor", "right.elbow", "--speed-deg-s", "5", "--duration-s", "0.05");

        Assert.Equal(1, code);
        Assert.Contains("right.elbow:", output, StringComparison.Ordinal);
        Assert.Equal(string.Empty, error);
    }

    [Theory]
    [InlineData("--speed-deg-s", "NaN")]
    [InlineData("--duration-s", "-1")]
    public void A_nonsense_speed_or_duration_is_refused_before_the_bus_is_touched(string option, string value)
    {
        using var silent = new PtyBus(serve: false);

        // Nothing serves this pty: a command that got past parsing would report missing modules, not the option.
        Cli.AssertRefused(silent.Run("jog", "--motor", "right.elbow", option, value), option);
    }

    public void Dispose() => Directory.Delete(_root, recursive: true);

    private string RobotWithout(int moduleId) => Cli.CopyRobot(_root, json =>
    {
        var layout = json["modules"]!["layout"]!.AsArray();
        layout.Remove(layout.First(m => m!["id"]!.GetValue<int>() == moduleId));
    });
}
