using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Simulation.Bus;
using RobotControl.Simulation.Native;

namespace RobotControl.Simulation;

/// <summary>Commissioning: a new virtual robot's modules get the robot file's parameters, are homed from their pots and moved to the bus baud.</summary>
public sealed partial class VirtualRobot
{
    private void Commission()
    {
        var table = ControlTable.Firmware;
        using var client = new BusClient(new VirtualLink(this), _clock);
        Span<byte> value = stackalloc byte[4];
        foreach (var module in _modules)
        {
            foreach (var p in ModuleParameters.For(Definition, module, table).Where(p => p.Field.Name != "baud_rate"))
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
        if (BaudRate != FactoryBaud)
        {
            var code = ModuleParameters.BaudCode(BaudRate);
            if (code < 0)
            {
                throw new ArgumentException($"{BaudRate} baud is not one the modules support");
            }

            foreach (var module in _modules)
            {
                var reply = client.Write(module.Id, table["baud_rate"].At(0), [(byte)code]);
                if (!reply.Succeeded)
                {
                    throw new InvalidOperationException($"commissioning module {module.Id}: setting {BaudRate} baud failed ({reply})");
                }
            }

            Advance(TimeSpan.FromMilliseconds(1));
            FirmwareHost.Check(FirmwareHost.BusSetBaud(_bus, (uint)BaudRate), "rcfw_bus_set_baud");
            _byteUs = 10e6 / BaudRate;
        }

        Advance(TimeSpan.FromMilliseconds(5));
    }
}
