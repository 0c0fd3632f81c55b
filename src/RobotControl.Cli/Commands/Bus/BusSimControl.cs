using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Host.Harness;
using RobotControl.Simulation;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// What a lab does to a box of boards, typed on <c>bus-sim --factory</c>'s standard input one line at a time:
/// <c>connect</c> (the next module still in the box), <c>connect &lt;module&gt;</c>, <c>disconnect &lt;module&gt;</c>,
/// <c>power-cycle &lt;module&gt;</c>, <c>status</c>, <c>truth</c> (every axis's true output angle, what a calibration
/// is checked against). A module is named as in the robot file (<c>arm.location</c>, its
/// name or its ID there). Each line is handed to the serving thread (<see cref="VirtualRobot.Post"/>), which answers
/// with one line.
/// </summary>
internal static class BusSimControl
{
    /// <summary>The commands, for the start-up line and refusals.</summary>
    public const string Syntax = "connect [<module>] | disconnect <module> | power-cycle <module> | status | truth";

    /// <summary>Reads <paramref name="input"/> on a background thread until it ends, posting each line to <paramref name="sim"/>.</summary>
    public static void Listen(VirtualRobot sim, TextReader input, TextWriter output)
    {
        var reader = new Thread(() =>
        {
            while (input.ReadLine() is { } line)
            {
                if (!string.IsNullOrWhiteSpace(line))
                {
                    sim.Post(s => Answer(s, line, output));
                }
            }
        })
        { IsBackground = true, Name = "bus-sim stdin" };
        reader.Start();
    }

    /// <summary>Carries out one command line on the serving thread and writes its one-line answer.</summary>
    internal static void Answer(VirtualRobot sim, string line, TextWriter output)
    {
        var words = line.Split(' ', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        var verb = words[0].ToLowerInvariant();
        var argument = words.Length > 1 ? string.Join(' ', words[1..]) : null;
        try
        {
            output.WriteLine((verb, argument) switch
            {
                ("connect", null) => sim.ConnectNext() is { } next ? Connected(sim, next) : "every module is plugged in already",
                ("connect", _) => Connected(sim, Resolve(sim, argument, verb), connect: true),
                ("disconnect", _) when argument is not null => Unplugged(sim, Resolve(sim, argument, verb)),
                ("power-cycle", _) when argument is not null => PowerCycled(sim, Resolve(sim, argument, verb)),
                ("status", null) => string.Join("; ", sim.Definition.Modules.Modules.Select(m => State(sim, m))),
                ("truth", null) => "truth: " + string.Join("; ", sim.Axes.Select(a => string.Create(CultureInfo.InvariantCulture, $"{a.Config.FullName} {a.OutputAngleRad * 180 / Math.PI:F3} deg"))),
                _ => $"'{line.Trim()}': unknown command (known: {Syntax})",
            });
        }
        catch (Exception ex) when (ex is FormatException or InvalidOperationException or KeyNotFoundException)
        {
            output.WriteLine(ex.Message);
        }

        output.Flush();
    }

    private static byte Resolve(VirtualRobot sim, string module, string verb) => HeadlessRun.ResolveModule(sim.Definition, module, verb);

    private static string Connected(VirtualRobot sim, byte module, bool connect = false)
    {
        if (connect)
        {
            sim.Connect(module);
        }

        return $"connected {Name(sim, module)}: it answers at id {sim.BusId(module)}";
    }

    private static string Unplugged(VirtualRobot sim, byte module)
    {
        sim.Disconnect(module);
        return $"unplugged {Name(sim, module)}";
    }

    private static string PowerCycled(VirtualRobot sim, byte module)
    {
        sim.PowerCycle(module);
        return $"power-cycled {Name(sim, module)}: it answers at id {sim.BusId(module)}";
    }

    private static string State(VirtualRobot sim, ModuleDefinition module) =>
        sim.IsConnected(module.Id) ? $"{Name(sim, module.Id)} at id {sim.BusId(module.Id)}" : $"{Name(sim, module.Id)} in the box";

    private static string Name(VirtualRobot sim, byte module) => $"module {module} ({sim.Definition.Modules.ById(module)!.Name})";
}
