using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.Simulation;

/// <summary>Commissioning a new (not factory) <see cref="VirtualRobot"/>: its modules get the robot file's parameters over the bus, are homed from their pots and moved to the bus baud.</summary>
internal static class VirtualCommissioning
{
    public static void Run(VirtualRobot robot)
    {
        var table = ControlTable.Firmware;
        var modules = robot.Definition.Modules.Modules;
        using var client = new BusClient(robot.OpenLink(), robot.Clock);
        Span<byte> value = stackalloc byte[4];
        foreach (var module in modules)
        {
            foreach (var p in ModuleParameters.For(robot.Definition, module, table).Where(p => p.Field.Name != "baud_rate"))
            {
                p.Field.Encode(p.Value, value);
                var reply = client.Write(module.Id, p.Address, value[..p.Field.Size]);
                if (!reply.Succeeded)
                {
                    throw new InvalidOperationException($"commissioning module {module.Id}: writing {p} failed ({reply})");
                }
            }

            // A freshly calibrated module has never been homed: home every motor from its pot.
            var mask = (byte)module.Motors.Aggregate(0, (acc, m) => acc | (1 << m.Channel));
            var homed = client.Write(module.Id, table["home_request"].At(0), [mask]);
            if (!homed.Succeeded)
            {
                throw new InvalidOperationException($"commissioning module {module.Id}: homing failed ({homed})");
            }
        }

        // Last, the baud (it takes effect after the reply); then the host side follows.
        if (robot.BaudRate != VirtualRobot.FactoryBaud)
        {
            var code = ModuleParameters.BaudCode(robot.BaudRate);
            if (code < 0)
            {
                throw new ArgumentException($"{robot.BaudRate} baud is not one the modules support");
            }

            foreach (var module in modules)
            {
                var reply = client.Write(module.Id, table["baud_rate"].At(0), [(byte)code]);
                if (!reply.Succeeded)
                {
                    throw new InvalidOperationException($"commissioning module {module.Id}: setting {robot.BaudRate} baud failed ({reply})");
                }
            }

            robot.Advance(TimeSpan.FromMilliseconds(1));
            robot.SetLineBaud(robot.BaudRate);
        }

        robot.Advance(TimeSpan.FromMilliseconds(5));
    }
}
