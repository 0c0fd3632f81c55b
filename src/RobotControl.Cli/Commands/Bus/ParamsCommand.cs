using System.CommandLine;
using RobotControl.Bus.Protocol;
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
        var command = new Command("params", "Read or write the modules' FRAM parameters.");
        var busOptions = new BusOptions(command);
        command.Subcommands.Add(BuildGet());
        command.Subcommands.Add(BuildSet());
        return command;
    }

    private static Command BuildGet()
    {
        var module = new Option<int?>("--module") { Description = "Only this module ID" };
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
                foreach (var c in bus.Controllers.Where(c => c.Present && (only is null || c.Id == only)))
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

    private static Command BuildSet()
    {
        var module = new Option<int?>("--module") { Description = "Module ID" };
        var field = new Option<string?>("--field") { Description = "Control-table field, e.g. kp, current_limit, speed_limit" };
        var motor = new Option<int>("--motor") { Description = "Motor channel for per-motor fields", DefaultValueFactory = _ => 0 };
        var value = new Option<long?>("--value") { Description = "Value in the field's units (see docs/protocol.md)" };
        var fromFile = new Option<bool>("--from-robot-file") { Description = "Write every parameter the robot file implies into every module" };
        var command = new Command("set", "Write one parameter (--module --field [--motor] --value) or all of them (--from-robot-file) into FRAM.");
        var busOptions = new BusOptions(command);
        foreach (var o in new Option[] { module, field, motor, value, fromFile })
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
                    output.WriteLine($"wrote {bus.WriteParameters()} values; {bus.CheckParameters().Count} differ now");
                    return 0;
                }

                if (parse.GetValue(module) is not { } id || parse.GetValue(field) is not { } name || parse.GetValue(value) is not { } v)
                {
                    throw new ArgumentException("give --module, --field and --value (or --from-robot-file)");
                }

                var back = bus.WriteParameter((byte)id, name, parse.GetValue(motor), v);
                output.WriteLine($"module {id}: {name}[{parse.GetValue(motor)}] = {back} (read back)");
                return 0;
            });
        });
        return command;
    }
}
