using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Modules;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>discover --scan-bauds [--yes]</c>: a complete broadcast ping at every baud the control table's <c>baud_rate</c>
/// codes name, listing the modules that answer at each. With a robot file, the robot's modules found at another baud
/// than the file's are offered a way back: the command to run, or with <c>--yes</c> the move itself (motors off, the
/// file's baud written at the baud the module answers at, then a ping at the file's baud to verify). Exit 0 when every
/// module of the robot file answers at the file's baud at the end, 1 otherwise.
/// </summary>
internal static class BaudScan
{
    /// <summary>Scans <paramref name="line"/>; returns the exit code.</summary>
    /// <exception cref="ArgumentException">The transport cannot change baud, or --yes without a robot file.</exception>
    public static int Run(BusLine line, bool bringBack, TextWriter output)
    {
        line.RequireBaudSwitchable("--scan-bauds");
        if (bringBack && line.RobotFile is null)
        {
            throw new ArgumentException("--yes: bringing modules back needs the robot file (--robot) for the baud to bring them to; nothing was written");
        }

        var found = new List<(int Baud, PingInfo Module)>();
        RobotDefinition? robot = null;
        foreach (var baud in SupportedBauds())
        {
            using var at = line.Open(baud, BusClient.BroadcastPingSpan(baud) + line.Options.ResponseMargin);
            robot ??= at.Definition;
            var answered = new PingInfo[253];
            var n = at.Client.Discover(answered);
            output.WriteLine($"at {baud,7} baud: {(n == 0 ? "no module" : string.Join(", ", answered.Take(n).OrderBy(p => p.Id).Select(p => $"id {p.Id} (model {p.ModelNumber}, firmware {p.FirmwareVersion})")))}");
            found.AddRange(answered.Take(n).Select(p => (baud, p)));
        }

        if (robot is null)
        {
            output.WriteLine($"{found.Count} module(s) answered; give --robot to compare them with a robot file");
            return 0;
        }

        var target = robot.Modules.BaudRate;
        var model = (ushort)ControlTable.Firmware["model_number"].Default;
        var strays = found.Where(f => f.Baud != target && f.Module.ModelNumber == model && robot.Modules.Modules.Any(m => m.Id == f.Module.Id)).ToList();
        var missing = robot.Modules.Modules.Where(m => found.All(f => f.Module.Id != m.Id)).ToList();
        foreach (var module in missing)
        {
            output.WriteLine($"MISSING  id {module.Id,3}  {module.Name}: answers at no supported baud");
        }

        foreach (var f in found.Where(f => robot.Modules.Modules.All(m => m.Id != f.Module.Id)))
        {
            output.WriteLine($"UNKNOWN  id {f.Module.Id,3}  at {f.Baud} baud: not in the robot file, left as it is");
        }

        foreach (var (baud, module) in strays)
        {
            output.WriteLine($"ELSEWHERE id {module.Id,3}  {Name(robot, module.Id)}: answers at {baud} baud, the robot file says {target}");
        }

        if (strays.Count == 0)
        {
            var all = robot.Modules.Modules.All(m => found.Any(f => f.Module.Id == m.Id && f.Baud == target));
            output.WriteLine(all ? $"every module of {robot.Name} answers at the robot file's {target} baud" : $"nothing to bring back to {target} baud");
            return all ? 0 : 1;
        }

        if (!bringBack)
        {
            output.WriteLine($"to bring {(strays.Count == 1 ? "it" : $"these {strays.Count} modules")} back to {target} baud run: robotctl discover {line.Transport(target)} --robot {line.RobotFile} --scan-bauds --yes");
            return 1;
        }

        return BringBack(line, robot, strays, target, output) == 0 && missing.Count == 0 ? 0 : 1;
    }

    /// <summary>Every bit rate the control table's <c>baud_rate</c> codes name, lowest code first.</summary>
    private static IEnumerable<int> SupportedBauds()
    {
        var field = ControlTable.Firmware["baud_rate"];
        for (var code = (int)field.Min; code <= (int)field.Max; code++)
        {
            if (ModuleParameters.BaudFromCode(code) is var baud and > 0)
            {
                yield return baud;
            }
        }
    }

    private static int BringBack(BusLine line, RobotDefinition robot, List<(int Baud, PingInfo Module)> strays, int target, TextWriter output)
    {
        var table = ControlTable.Firmware;
        var torque = table["torque_enable"];
        byte[] off = new byte[torque.Count]; // every motor's torque_enable, one write (stride 1)
        byte[] code = [(byte)ModuleParameters.BaudCode(target)];
        var moved = new List<byte>();
        foreach (var group in strays.GroupBy(s => s.Baud))
        {
            using var at = line.Open(group.Key);
            foreach (var (_, module) in group)
            {
                var reply = at.Client.Write(module.Id, torque.At(0), off);
                if (reply.Succeeded)
                {
                    reply = at.Client.Write(module.Id, table["baud_rate"].At(0), code); // it switches after this reply
                }

                output.WriteLine(reply.Succeeded
                    ? $"module {module.Id}: motors off, baud_rate {code[0]} ({target} baud) written at {group.Key} baud"
                    : $"module {module.Id}: NOT moved, it refused at {group.Key} baud ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}); it stays there");
                if (reply.Succeeded)
                {
                    moved.Add(module.Id);
                }
            }
        }

        using var home = line.Open(target);
        var back = moved.Where(id => home.Client.Ping(id, out _).Succeeded).ToList();
        foreach (var id in moved.Except(back))
        {
            output.WriteLine($"module {id} \"{Name(robot, id)}\": does NOT answer at {target} baud after the change; scan again");
        }

        output.WriteLine($"{back.Count} of {strays.Count} module(s) brought back to {target} baud (verified by ping){(back.Count == strays.Count ? string.Empty : "; the rest are listed above")}");
        return back.Count == strays.Count ? 0 : 1;
    }

    private static string Name(RobotDefinition robot, byte id) => robot.Modules.Modules.First(m => m.Id == id).Name;
}
