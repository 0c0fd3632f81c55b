using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests;

/// <summary>
/// <see cref="VirtualAxis.HallFailedCode"/> against the real firmware: Hall lines stuck at an invalid code latch the
/// module's Hall error once (the one edge to it) and freeze its count while the rotor turns; the code is checked.
/// </summary>
public sealed class VirtualAxisHallFaultTests
{
    private const byte Module = 2; // the right upper arm: the elbow on channel 0
    private static readonly ControlTable Table = ControlTable.Firmware;

    [Theory]
    [InlineData(7)] // the connector off: the pull-ups read 111
    [InlineData(0)] // the lines shorted to ground
    public void Hall_lines_stuck_at_an_invalid_code_latch_the_Hall_error_and_freeze_the_count_while_the_motor_turns(int code)
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(ShippedRobots.Lb, clock);
        using var client = new BusClient(sim.OpenLink(), clock);
        var reader = new ParameterWriter(client, Table);
        var elbow = sim.Axis(0, "elbow");
        Assert.True(client.Write(Module, Table["hardware_error_status"].At(0), [0]).Succeeded);
        var start = reader.Read(Module, "present_position", 0);
        var angle = elbow.OutputAngleRad;

        elbow.HallFailedCode = code;
        var goal = new byte[4];
        Table["goal_position"].Encode(start + elbow.Config.ToCounts(20 * Math.PI / 180), goal);
        Assert.True(client.Write(Module, Table["goal_position"].At(0), goal).Succeeded);
        Assert.True(client.Write(Module, Table["torque_enable"].At(0), [1]).Succeeded);
        sim.Advance(TimeSpan.FromMilliseconds(300));

        Assert.True(Math.Abs(elbow.OutputAngleRad - angle) > 2 * Math.PI / 180, "the elbow did not turn");
        Assert.Equal(start, reader.Read(Module, "present_position", 0));
        Assert.True(((HardwareErrors)reader.Read(Module, "hardware_error_status", 0)).HasFlag(HardwareErrors.Hall));
        Assert.True(((HardwareErrors)reader.Read(Module, "motor_error", 0)).HasFlag(HardwareErrors.Hall));
        Assert.Equal(1, reader.Read(Module, "hall_error_count", 0));
        Assert.True(client.Write(Module, Table["torque_enable"].At(0), [0]).Succeeded);
    }

    [Fact]
    public void A_Hall_code_is_three_bits()
    {
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(ShippedRobots.Lb, clock);
        var elbow = sim.Axis(0, "elbow");
        Assert.Throws<ArgumentOutOfRangeException>(() => elbow.HallFailedCode = 8);
        Assert.Throws<ArgumentOutOfRangeException>(() => elbow.HallFailedCode = -1);
        Assert.Null(elbow.HallFailedCode);
    }
}
