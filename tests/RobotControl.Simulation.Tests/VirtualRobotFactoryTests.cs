using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Simulation.Tests;

/// <summary>A virtual LB-1.0 as a box of boards fresh from the factory (<see cref="VirtualRobotOptions.Factory"/>).</summary>
public sealed class VirtualRobotFactoryTests
{
    private static readonly ControlTable Table = ControlTable.Firmware;

    [Fact]
    public void From_the_factory_a_module_answers_only_at_the_default_id_with_the_default_parameters()
    {
        var (sim, client) = Factory(connected: 1);
        using (sim)
        using (client)
        {
            var found = new PingInfo[16];
            var n = client.Discover(found);
            Assert.Equal(1, n);
            Assert.Equal((int)ControlTable.Firmware["id"].Default, found[0].Id);
            Assert.Equal(VirtualRobot.FactoryId, found[0].Id);
            Assert.Equal(VirtualRobot.FactoryBaud, sim.LineBaud);

            // Every persistent field the host may write reads back as the control table's default (blank FRAM).
            var area = Table.Fields.Where(f => f.Persistent && f.Writable).ToList();
            Assert.NotEmpty(area);
            var value = new byte[4];
            foreach (var field in area)
            {
                for (var k = 0; k < field.Count; k++)
                {
                    var reply = client.Read(VirtualRobot.FactoryId, field.At(k), value.AsSpan(0, field.Size));
                    Assert.True(reply.Succeeded, $"{field.Name}[{k}]: {reply}");
                    Assert.Equal((long)field.Default, field.Decode(value.AsSpan(0, field.Size)));
                }
            }
        }
    }

    [Fact]
    public void Two_boards_plugged_in_at_once_answer_together_and_collide()
    {
        var (sim, client) = Factory(connected: 2);
        using (sim)
        using (client)
        {
            var before = sim.Collisions;
            _ = client.Ping(VirtualRobot.FactoryId, out _);
            Assert.True(sim.Collisions > before, "two modules at the factory ID answered a ping without a collision");
        }
    }

    [Fact]
    public void An_id_written_over_the_bus_is_kept_across_a_power_cycle()
    {
        var (sim, client) = Factory(connected: 1);
        using (sim)
        using (client)
        {
            var board = sim.Definition.Modules.Modules[0].Id;
            const byte NewId = 42;
            Renumber(client, NewId);
            sim.PowerCycle(board);
            Assert.Equal(NewId, sim.BusId(board));
            Assert.True(client.Ping(NewId, out _).Succeeded, "the renumbered module lost its ID in a power cycle");
            Assert.False(client.Ping(VirtualRobot.FactoryId, out _).Succeeded);
        }
    }

    [Fact]
    public void Boards_are_plugged_in_one_at_a_time_and_an_unplugged_one_is_silent()
    {
        var (sim, client) = Factory(connected: 0);
        using (sim)
        using (client)
        {
            var found = new PingInfo[16];
            Assert.Equal(0, client.Discover(found));
            var modules = sim.Definition.Modules.Modules;
            Assert.Throws<InvalidOperationException>(() => sim.PowerCycle(modules[0].Id));
            byte nextId = 100;
            foreach (var module in modules)
            {
                Assert.False(sim.IsConnected(module.Id));
                Assert.Equal(module.Id, sim.ConnectNext());
                Assert.True(sim.IsConnected(module.Id));
                Assert.Equal(VirtualRobot.FactoryId, sim.BusId(module.Id));
                Renumber(client, nextId);
                nextId++;
            }

            Assert.Null(sim.ConnectNext());
            var n = client.Discover(found);
            Assert.Equal(Enumerable.Range(100, modules.Count), found.Take(n).Select(p => (int)p.Id).Order());

            sim.Disconnect(modules[0].Id);
            Assert.False(client.Ping(100, out _).Succeeded);
            sim.Connect(modules[0].Id);
            Assert.True(client.Ping(100, out _).Succeeded);
        }
    }

    [Fact]
    public void Factory_options_that_cannot_be_are_refused()
    {
        var clock = new ManualTimeProvider();
        var baud = Assert.Throws<ArgumentException>(() => new VirtualRobot(VirtualLb.Lb, clock, new VirtualRobotOptions { Factory = true, BaudRate = 3_000_000 }));
        Assert.Contains("factory baud", baud.Message, StringComparison.Ordinal);
        var count = Assert.Throws<ArgumentException>(() => new VirtualRobot(VirtualLb.Lb, clock, new VirtualRobotOptions { Factory = true, ConnectedAtStart = 7 }));
        Assert.Contains("ConnectedAtStart 7: the robot has 6 modules", count.Message, StringComparison.Ordinal);
        Assert.Throws<ArgumentException>(() => new VirtualRobot(VirtualLb.Lb, clock, new VirtualRobotOptions { ConnectedAtStart = 1 }));
    }

    /// <summary>Gives the module at the factory ID <paramref name="id"/> (it answers from its new ID, so the write's own reply is not awaited) and checks it answers there.</summary>
    private static void Renumber(BusClient client, byte id)
    {
        _ = client.Write(VirtualRobot.FactoryId, Table["id"].At(0), [id]);
        Assert.True(client.Ping(id, out _).Succeeded, $"no module answers at ID {id} after it was written");
    }

    private static (VirtualRobot Sim, BusClient Client) Factory(int connected)
    {
        var clock = new ManualTimeProvider();
        var sim = new VirtualRobot(VirtualLb.Lb, clock, new VirtualRobotOptions { Factory = true, ConnectedAtStart = connected });
        return (sim, new BusClient(sim.OpenLink(), clock));
    }
}
