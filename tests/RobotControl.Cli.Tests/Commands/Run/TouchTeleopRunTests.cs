using RobotControl.Cli.Tests.Commands.Devices;
using RobotControl.Tests.FakeHd;

namespace RobotControl.Cli.Tests.Commands.Run;

[Collection(FakeHdCollection.Name)]
public sealed class TouchTeleopRunTests
{
    [Fact]
    public void The_teleop_graph_with_both_hands_on_openhaptics_runs_headless_on_the_fake_library()
    {
        var graph = Path.Combine(FakeHdLibrary.RepoRoot(), "graphs", "teleop-lb-touch.json");

        // The graph names no library: robotctl finds the fake through LD_LIBRARY_PATH, as it would find libHD.so.
        var (code, output, error) = DevicesCommandTests.Robotctl(
            new Dictionary<string, string> { ["LD_LIBRARY_PATH"] = FakeHdLibrary.Folder },
            "run", graph, "--virtual", "--duration", "2s");

        Assert.True(code == 0, output + error);
        Assert.Contains("summary: 2000 ticks", output, StringComparison.Ordinal);
        Assert.Contains("faults: 0", output, StringComparison.Ordinal);
    }
}
