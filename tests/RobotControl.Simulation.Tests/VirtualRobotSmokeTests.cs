using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Loading;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests;

public sealed class VirtualRobotSmokeTests
{
    [Fact]
    public void Modules_answer_and_report_the_pot_homed_positions()
    {
        var robot = RobotLoader.Load(RepositoryPaths.Robot("lb-1.0.json"));
        var clock = new ManualTimeProvider();
        using var sim = new VirtualRobot(robot, clock);
        using var client = new BusClient(sim.OpenLink(), clock);
        Span<PingInfo> found = stackalloc PingInfo[16];
        var n = client.Discover(found);
        Assert.Equal(6, n);
        var table = ControlTable.Firmware;
        Span<byte> data = stackalloc byte[4];
        foreach (var axis in sim.Axes)
        {
            Assert.True(client.Read(axis.Config.ModuleId, table["present_position"].At(axis.Config.Channel), data).Succeeded);
            var counts = System.Buffers.Binary.BinaryPrimitives.ReadInt32LittleEndian(data);
            Assert.InRange(axis.Config.ToRadians(counts) - axis.OutputAngleRad, -0.02, 0.02);
        }
    }
}
