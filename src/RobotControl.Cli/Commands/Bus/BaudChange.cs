using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Host.Session;
using RobotControl.Modules;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>params set --field baud_rate --value C --yes</c>: moves the whole bus to another baud, the modules first and then
/// the host. Every module of the robot file must answer at the present baud (a module left behind would be cut off);
/// the motors are turned off; each module registers the new baud (REG WRITE, checked and acknowledged) and one broadcast
/// ACTION makes them all switch at once; the host re-opens its port at the new baud and pings every module. When a
/// module does not answer there, the host looks for it at the old baud and says which module is where and the one
/// command that brings every module back to the robot file's baud.
/// </summary>
internal static class BaudChange
{
    /// <summary>Runs the change on <paramref name="session"/> (opened at the present baud); returns the exit code.</summary>
    /// <exception cref="ArgumentException">The code, an option or the transport is wrong, or it is not confirmed (nothing was written).</exception>
    /// <exception cref="IOException">The bus is not as the robot file says, or a module refused (nothing changed).</exception>
    public static int Run(RobotConnection session, BusLine line, long code, (bool Module, int Motor) given, bool confirmed, TextWriter output)
    {
        ParameterWriter.CheckValue(ControlTable.Firmware["baud_rate"], 0, code);
        var baud = ModuleParameters.BaudFromCode((int)code);
        if (baud == 0)
        {
            throw new ArgumentException($"--value: the control table names no bit rate for baud_rate code {code}; nothing was written");
        }

        if (given.Module)
        {
            throw new ArgumentException("--module: baud_rate is changed in every module of the bus at once (a bus runs at one baud); leave --module out");
        }

        if (given.Motor != 0)
        {
            throw new ArgumentException("--motor: baud_rate is one value per module; leave --motor out");
        }

        line.RequireBaudSwitchable("--field baud_rate");
        var bus = session.RequireRobot();
        var from = session.Client.Link.BaudRate;
        var ids = bus.Controllers.Select(c => c.Id).ToArray();
        if (!confirmed)
        {
            throw new ArgumentException($"--yes: this writes baud_rate {code} ({baud} baud) into all {ids.Length} modules of {bus.Definition.Name} (motors off), then re-opens {session.Client.Link.Description} at {baud} baud and pings every module; add --yes to do it (nothing was written)");
        }

        var report = bus.Discover();
        if (!report.AllAsConfigured)
        {
            throw new IOException($"the bus at {from} baud is not as the robot file says ({string.Join("; ", report.Problems.Select(p => p.Line.Trim()))}); a baud change must reach every module at once, so nothing was written (find the others with robotctl discover --scan-bauds)");
        }

        if (baud == from)
        {
            output.WriteLine($"every module already answers at {baud} baud (baud_rate {code}); nothing was written");
            return 0;
        }

        bus.EnableTorque(false);
        Register(session.Client, bus.Controllers.Select(c => (c.Id, c.Name)).ToArray(), (byte)code, (byte)ModuleParameters.BaudCode(from), from);
        session.Client.ActionAll();
        output.WriteLine($"motors off; baud_rate {code} registered in modules {string.Join(", ", ids)} and applied by one broadcast ACTION at {from} baud");

        // The host side: its port is re-opened at the new baud (the old one is released first: it holds the device).
        session.Dispose();
        return Verify(line, bus.Definition, from, baud, output);
    }

    /// <summary>
    /// The host's side of a change from <paramref name="from"/> to <paramref name="baud"/> that the modules were told
    /// to make: opens the line at the new baud and pings every module of <paramref name="robot"/>. All answer: exit 0.
    /// Otherwise looks for the silent ones at the old baud and prints where each module is and the command that brings
    /// them all back to the robot file's baud: exit 1.
    /// </summary>
    internal static int Verify(BusLine line, RobotDefinition robot, int from, int baud, TextWriter output)
    {
        var ids = robot.Modules.Modules.Select(m => m.Id).ToArray();
        List<byte> silent;
        using (var after = line.Open(baud))
        {
            silent = ids.Where(id => !after.Client.Ping(id, out _).Succeeded).ToList();
        }

        if (silent.Count == 0)
        {
            output.WriteLine($"baud changed: modules {string.Join(", ", ids)} answer a ping at {baud} baud; use the transport {line.Transport(baud)} from now on");
            if (robot.Modules.BaudRate != baud)
            {
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"the robot file still says modules.baud = {robot.Modules.BaudRate}: set it to {baud} (until then discover reports baud_rate as differing)"));
            }

            return 0;
        }

        ReportFailure(line, robot, from, baud, silent, output);
        return 1;
    }

    /// <summary>Registers the new code in every module; if one refuses, the others' registration is replaced by their present code.</summary>
    private static void Register(BusClient client, (byte Id, string Name)[] modules, byte code, byte present, int from)
    {
        var address = ControlTable.Firmware["baud_rate"].At(0);
        for (var i = 0; i < modules.Length; i++)
        {
            var reply = client.RegWrite(modules[i].Id, address, [code]);
            if (reply.Succeeded)
            {
                continue;
            }

            // A registered write waits for any later ACTION: withdraw the ones already made (re-register the present baud).
            var withdrawn = modules.Take(i).All(m => client.RegWrite(m.Id, address, [present]).Succeeded);
            throw new IOException($"module {modules[i].Id} \"{modules[i].Name}\" refused the new baud ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}); {(withdrawn ? "the others' registered change was withdrawn" : "withdrawing the others' registered change failed, do not send ACTION")}; every module stays at {from} baud");
        }
    }

    private static void ReportFailure(BusLine line, RobotDefinition robot, int from, int baud, List<byte> silent, TextWriter output)
    {
        List<byte> stayed;
        using (var old = line.Open(from))
        {
            stayed = silent.Where(id => old.Client.Ping(id, out _).Succeeded).ToList();
        }

        var moved = robot.Modules.Modules.Select(m => m.Id).Except(silent).ToArray();
        if (moved.Length > 0)
        {
            output.WriteLine($"modules {string.Join(", ", moved)} answer at {baud} baud");
        }

        foreach (var module in robot.Modules.Modules.Where(m => silent.Contains(m.Id)))
        {
            output.WriteLine(stayed.Contains(module.Id)
                ? $"NOT CHANGED module {module.Id} \"{module.Name}\": still answers at {from} baud, not at {baud}"
                : $"LOST        module {module.Id} \"{module.Name}\": answers neither at {from} nor at {baud} baud");
        }

        output.WriteLine($"the bus is split; to bring every module to the robot file's {robot.Modules.BaudRate} baud run: robotctl discover {line.Transport(robot.Modules.BaudRate)} --robot {line.RobotFile} --scan-bauds --yes");
    }
}
