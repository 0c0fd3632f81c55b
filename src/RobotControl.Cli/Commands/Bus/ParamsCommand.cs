using System.CommandLine;
using RobotControl.Bus.Protocol;
using RobotControl.Cli.Options;
using RobotControl.Modules;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl params get|set &lt;transport&gt;</c>: read the modules' persistent (FRAM) parameters next to the robot
/// file's values, write one value, or write the robot file's values into every module.
/// </summary>
internal sealed class ParamsCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        // The transport belongs to get and set (params get <transport>), not to params itself.
        var command = new Command("params", "Read or write the modules' FRAM parameters.");
        command.Subcommands.Add(BuildGet());
        command.Subcommands.Add(BuildSet());
        return command;
    }

    private static Command BuildGet()
    {
        var module = ModuleOption("Only this module ID");
        var command = new Command("get", "Print every persistent parameter with the robot file's value (* marks a difference).");
        var busOptions = new BusOptions(command);
        command.Options.Add(module);
        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            return busOptions.Run(parse, session =>
            {
                var bus = session.RequireRobot();
                bus.Discover();
                var only = parse.GetValue(module);
                var differ = 0;
                var modules = bus.Controllers.Where(c => c.Present && (only is null || c.Id == only)).ToArray();
                if (modules.Length == 0)
                {
                    throw new IOException(only is null
                        ? $"no module of the robot file answers on {session.Client.Link.Description}"
                        : $"--module {only}: no module of the robot file with this ID answers on {session.Client.Link.Description}");
                }

                foreach (var c in modules)
                {
                    output.WriteLine($"module {c.Id} \"{c.Name}\"");
                    foreach (var p in ModuleParameters.For(session.Definition!, c.Definition, ControlTable.Firmware))
                    {
                        var actual = bus.ReadParameter(c.Id, p.Field.Name, p.Motor);
                        var mark = actual == p.Value ? " " : "*";
                        differ += actual == p.Value ? 0 : 1;
                        var name = p.Field.Count > 1 ? $"{p.Field.Name}[{p.Motor}]" : p.Field.Name;
                        output.WriteLine($" {mark} {name,-26} {actual,12}   file {p.Value,12}  ({p.Meaning})");
                    }
                }

                return differ == 0 ? 0 : 1;
            });
        });
        return command;
    }

    /// <summary>A module ID option, in the control table's <c>id</c> range.</summary>
    private static Option<int?> ModuleOption(string description)
    {
        var id = ControlTable.Firmware["id"];
        return CliOption.OptionalNumber("--module", description, (int)id.Min, (int)id.Max);
    }

    private static Command BuildSet()
    {
        var table = ControlTable.Firmware;
        var module = ModuleOption("Module ID");
        var field = new Option<string?>("--field") { Description = "Control-table field, e.g. kp, current_limit, speed_limit" };
        var motor = CliOption.Number("--motor", "Motor channel for per-motor fields", 0, table.MaxMotors - 1, 0);
        var writable = table.Fields.Where(f => f.Writable).ToArray();
        var value = CliOption.OptionalNumber("--value", "Value in the field's units (see docs/protocol.md); checked against the field's own range", writable.Min(f => (long)f.Min), writable.Max(f => (long)f.Max));
        var fromFile = new Option<bool>("--from-robot-file") { Description = "Write every parameter the robot file implies into every module" };
        var yes = new Option<bool>("--yes") { Description = "Confirm a write of id (the module then answers only at the new ID) or a change of baud_rate (every module, then the host; verified by ping)" };
        var protectionOff = new Option<bool>("--allow-protection-off") { Description = "Allow a value that switches a protection off (current_limit 0, speed_limit 0, bus_watchdog 0); a warning names what goes off" };
        var command = new Command("set", "Write one parameter (--module --field [--motor] --value) or all of them (--from-robot-file) into FRAM.");
        var busOptions = new BusOptions(command);
        foreach (var o in new Option[] { module, field, motor, value, fromFile, yes, protectionOff })
        {
            command.Options.Add(o);
        }

        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            return busOptions.Run(parse, session =>
            {
                var bus = session.RequireRobot();
                bus.Discover();
                if (parse.GetValue(fromFile))
                {
                    RequireFileBaud(session);
                    output.WriteLine($"wrote {bus.WriteParameters()} values; {bus.CheckParameters().Count} differ now");
                    return 0;
                }

                if (parse.GetValue(field) == "baud_rate" && parse.GetValue(value) is { } code)
                {
                    return BaudChange.Run(session, busOptions.Line(parse), code, (parse.GetValue(module) is not null, parse.GetValue(motor)), parse.GetValue(yes), output);
                }

                if (parse.GetValue(module) is not { } id || parse.GetValue(field) is not { } name || parse.GetValue(value) is not { } v)
                {
                    throw new ArgumentException("give --module, --field and --value (or --from-robot-file; baud_rate: --field and --value, every module at once)");
                }

                if (!table.Contains(name))
                {
                    throw new ArgumentException($"--field: the control table has no field '{name}' (writable: {string.Join(", ", table.Fields.Where(f => f.Writable).Select(f => f.Name))})");
                }

                var allowOff = parse.GetValue(protectionOff);
                ParameterGuard.CheckOne(session.Client, (byte)id, table[name], parse.GetValue(motor), v, (parse.GetValue(yes), allowOff));
                if (allowOff && ParameterRules.ProtectionOff(table[name], v) is { } off)
                {
                    parse.InvocationConfiguration.Error.WriteLine($"warning: module {id}: {off} (--allow-protection-off)");
                }

                var back = bus.WriteParameter((byte)id, name, parse.GetValue(motor), v, allowOff);
                output.WriteLine($"module {id}: {name}[{parse.GetValue(motor)}] = {back} (read back)");
                return 0;
            });
        });
        return command;
    }

    /// <summary>
    /// Writing the robot file's values includes its baud: refused when the bus runs at another one, since the modules
    /// would go silent in the middle of the writes (a baud change is its own procedure, <see cref="BaudChange"/>).
    /// </summary>
    private static void RequireFileBaud(Host.Session.RobotConnection session)
    {
        var fileBaud = session.Definition!.Modules.BaudRate;
        var lineBaud = session.Client.Link.BaudRate;
        if (fileBaud != lineBaud)
        {
            throw new ArgumentException($"--from-robot-file: the robot file says modules.baud = {fileBaud} but the bus runs at {lineBaud} baud, and writing it would cut the modules off halfway; change the bus first (params set --field baud_rate --value {ModuleParameters.BaudCode(fileBaud)} --yes) or fix the file; nothing was written");
        }
    }
}
