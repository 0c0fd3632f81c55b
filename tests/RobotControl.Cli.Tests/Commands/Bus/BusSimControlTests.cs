using RobotControl.Cli.Commands.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Cli.Tests.Commands.Bus;

/// <summary>The lines <c>bus-sim --factory</c> takes on standard input (<see cref="BusSimControl"/>), each answered in one line.</summary>
public sealed class BusSimControlTests
{
    [Fact]
    public void Each_line_does_what_it_says_and_answers_in_one_line()
    {
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider(), new VirtualRobotOptions { Factory = true, ConnectedAtStart = 5 });
        Assert.Equal("connected module 13 (left forearm): it answers at id 1", Answer(sim, "connect"));
        Assert.True(sim.IsConnected(13));
        Assert.Equal("every module is plugged in already", Answer(sim, "connect"));
        Assert.Equal("unplugged module 2 (right upper arm)", Answer(sim, "disconnect right.upper_arm"));
        Assert.False(sim.IsConnected(2));
        Assert.Equal("cannot power-cycle module 2 (right upper arm): it is not plugged in (connect it first)", Answer(sim, "power-cycle 2"));
        Assert.Equal("connected module 2 (right upper arm): it answers at id 1", Answer(sim, "CONNECT right upper arm"));
        Assert.Equal("power-cycled module 11 (left shoulder): it answers at id 1", Answer(sim, "power-cycle left.shoulder"));
        sim.Disconnect(3);
        Assert.Contains("module 3 (right forearm) in the box; module 11 (left shoulder) at id 1", Answer(sim, "status"), StringComparison.Ordinal);
    }

    [Fact]
    public void Truth_gives_every_axis_its_true_output_angle_in_degrees()
    {
        var pose = new[] { -30.0, 10.0, 20.0, 40.0, 90.0 }.Select(d => d * Math.PI / 180).ToArray();
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider(), new VirtualRobotOptions { Factory = true, InitialJointsRad = [pose, pose], InitialJawRad = 15 * Math.PI / 180 });
        var truth = Answer(sim, "truth");
        // shoulder_1 = yaw + pitch, shoulder_2 = yaw - pitch, shoulder_3 = roll - yaw - pitch (the robot file's couplings).
        Assert.StartsWith("truth: right.shoulder_yaw -20.000 deg; right.shoulder_pitch -40.000 deg; right.shoulder_roll 40.000 deg; right.elbow 40.000 deg; right.tool_roll 90.000 deg; right.tool_open_close 15.000 deg; left.shoulder_yaw -20.000 deg", truth, StringComparison.Ordinal);
        Assert.Equal(sim.Axes.Count, truth.Split("; ").Length);
    }

    [Fact]
    public void A_line_it_does_not_know_is_refused_with_what_it_knows()
    {
        using var sim = new VirtualRobot(VirtualLb.Lb, new ManualTimeProvider(), new VirtualRobotOptions { Factory = true });
        Assert.Equal($"'plug in': unknown command (known: {BusSimControl.Syntax})", Answer(sim, "plug in"));
        Assert.Equal($"'disconnect': unknown command (known: {BusSimControl.Syntax})", Answer(sim, "disconnect"));
        Assert.StartsWith("connect: no module 'left.knee' (known: right.shoulder (id 1), ", Answer(sim, "connect left.knee"), StringComparison.Ordinal);
        Assert.All(sim.Definition.Modules.Modules, m => Assert.False(sim.IsConnected(m.Id)));
    }

    private static string Answer(VirtualRobot sim, string line)
    {
        using var output = new StringWriter();
        BusSimControl.Answer(sim, line, output);
        var lines = output.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Single(lines);
        return lines[0].TrimEnd('\r');
    }
}
