using System.CommandLine;
using System.Globalization;
using System.Runtime.InteropServices;
using RobotControl.Bus.Transports;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Cli.Options;
using RobotControl.Definitions.Loading;
using RobotControl.Modules;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.Simulation.Units;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl bus-sim &lt;robot file&gt; --pty [--baud 3000000]</c>: presents a virtual robot's bus (every module running the real
/// firmware) on a pseudo-terminal, in real time, until interrupted; <c>--device</c> serves an existing tty instead
/// (e.g. one end of a socat pty pair). <c>--factory</c>: a box of boards (every module blank, at the default ID, plugged
/// in one at a time by lines on standard input, <see cref="BusSimControl"/>); <c>--unit-variation &lt;seed&gt;</c>: the
/// unit's own pot curves, printed at start.
/// </summary>
internal sealed class BusSimCommand : ICliCommand
{
    /// <inheritdoc />
    public Command Build()
    {
        var robot = new Argument<FileInfo>("robot") { Description = "Robot data file with a modules section, e.g. hardware/robots/lb-1.0.json" };
        var pty = new Option<bool>("--pty") { Description = "Create a pseudo-terminal and print its path" };
        var device = new Option<string?>("--device") { Description = "Serve an existing tty instead (e.g. a socat pty end)" };
        var seed = CliOption.Number("--seed", "Seed of the sensor noise", 0, int.MaxValue, 1);
        var seconds = CliOption.Number("--seconds", "Stop after this many seconds (0: until Ctrl+C)", 0.0, 7 * 86_400.0, 0.0);
        var baud = CliOption.OptionalNumber("--baud", "Commission the modules at this bit rate instead of the robot file's (e.g. 3000000)", 1, 100_000_000);
        var factory = new Option<bool>("--factory") { Description = $"Modules fresh from the factory: blank, all at the default ID, plugged in one at a time (type on stdin: {BusSimControl.Syntax})" };
        var connected = CliOption.Number("--connected", "With --factory: modules plugged in at start (robot file order)", 0, 253, 0);
        var unitVariation = CliOption.OptionalNumber("--unit-variation", "Seed of this unit's pot curves: each differs from the robot file's design curve (offset, gain, bow; docs/bring-up.md)", 0, int.MaxValue);
        var command = new Command("bus-sim", "Expose a virtual robot's module bus on a pty (real firmware, simulated motors).");
        command.Arguments.Add(robot);
        foreach (var o in new Option[] { pty, device, seed, seconds, baud, factory, connected, unitVariation })
        {
            command.Options.Add(o);
        }

        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            var error = parse.InvocationConfiguration.Error;
            try
            {
                if (parse.GetValue(baud) is { } rate && ModuleParameters.BaudCode(rate) < 0)
                {
                    error.WriteLine($"--baud {rate}: not a rate the modules support ({string.Join(", ", ModuleParameters.Bauds)})");
                    return 2;
                }

                var fromFactory = parse.GetValue(factory);
                if (fromFactory && parse.GetValue(baud) is { } commissioned)
                {
                    error.WriteLine($"--baud {commissioned}: modules from the factory run at the factory baud ({VirtualRobot.FactoryBaud}); commissioning moves them");
                    return 2;
                }

                if (!fromFactory && parse.GetValue(connected) != 0)
                {
                    error.WriteLine("--connected: only with --factory (modules from the factory are plugged in one at a time)");
                    return 2;
                }

                var definition = RobotLoader.Load(parse.GetValue(robot)!.FullName);
                if (parse.GetValue(connected) > definition.Modules.Modules.Count)
                {
                    error.WriteLine($"--connected {parse.GetValue(connected)}: {definition.Name} has {definition.Modules.Modules.Count} modules");
                    return 2;
                }

                var simulation = new VirtualRobotOptions
                {
                    Seed = parse.GetValue(seed),
                    BaudRate = parse.GetValue(baud),
                    Factory = fromFactory,
                    ConnectedAtStart = parse.GetValue(connected),
                    UnitVariationSeed = parse.GetValue(unitVariation),
                };
                using var sim = new VirtualRobot(definition, new ManualTimeProvider(), simulation);
                DescribeUnit(sim, output);
                IByteLink port;
                if (parse.GetValue(device) is { } path)
                {
                    port = SerialLink.Open(path, sim.BaudRate);
                    output.WriteLine($"serving {definition.Name} on {path}");
                }
                else if (parse.GetValue(pty))
                {
                    var terminal = PseudoTerminal.Create();
                    port = terminal;
                    output.WriteLine(fromFactory
                        ? $"serving {definition.Name} from the factory ({definition.Modules.Modules.Count} modules, {parse.GetValue(connected)} plugged in, each at id {VirtualRobot.FactoryId}) on serial:{terminal.SlavePath}?baud={sim.BaudRate}"
                        : $"serving {definition.Name} ({definition.Modules.Modules.Count} modules, ids {string.Join(",", definition.Modules.Modules.Select(m => m.Id))}) on serial:{terminal.SlavePath}?baud={sim.BaudRate}");
                }
                else
                {
                    error.WriteLine("give --pty or --device <tty>");
                    return 2;
                }

                if (fromFactory)
                {
                    output.WriteLine($"plug modules in on stdin: {BusSimControl.Syntax}");
                    BusSimControl.Listen(sim, Console.In, output);
                }

                output.Flush();
                using (port)
                using (var stop = new CancellationTokenSource())
                {
                    // Ctrl+C or SIGTERM ends serving and prints how it went (a benchmark stops its simulator so).
                    using var interrupt = PosixSignalRegistration.Create(PosixSignal.SIGINT, Stop);
                    using var terminate = PosixSignalRegistration.Create(PosixSignal.SIGTERM, Stop);
                    void Stop(PosixSignalContext context)
                    {
                        context.Cancel = true;
                        stop.Cancel();
                    }

                    if (parse.GetValue(seconds) > 0)
                    {
                        stop.CancelAfter(TimeSpan.FromSeconds(parse.GetValue(seconds)));
                    }

                    sim.Serve(port, stop.Token);
                }

                output.WriteLine(string.Create(
                    CultureInfo.InvariantCulture,
                    $"stopped after {sim.Elapsed.TotalSeconds:F1} s simulated: {sim.Serving.SlippedTime.TotalMilliseconds:F0} ms slipped behind real time, longest stall {sim.Serving.LongestServeGap.TotalMilliseconds:F1} ms at {sim.Serving.LongestServeGapAt.TotalSeconds:F3} s (process CPU in it {sim.Serving.LongestServeGapCpu.TotalMilliseconds:F1} ms), compiled while serving {sim.Serving.MethodsCompiledWhileServing} methods ({sim.Serving.CompileTimeWhileServing.TotalMilliseconds:F1} ms), {GC.CollectionCount(0)} collections ({GC.GetTotalPauseDuration().TotalMilliseconds:F1} ms paused)"));
                return 0;
            }
            catch (Exception ex) when (ex is IOException or RobotDataException or ArgumentException)
            {
                error.WriteLine(ex.Message);
                return 2;
            }
        });
        return command;
    }

    /// <summary>With unit variation: the bounds and every pot's true curve against its design (what a calibration is checked against).</summary>
    private static void DescribeUnit(VirtualRobot sim, TextWriter output)
    {
        if (sim.Axes.All(a => a.PotVariation == PotVariation.None))
        {
            return;
        }

        var b = PotVariationBounds.Default;
        output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"unit variation: each pot within offset ±{b.OffsetCounts} counts, gain ±{b.GainFraction * 100} %, bow ±{b.BowCounts} counts of its design curve"));
        foreach (var axis in sim.Axes)
        {
            var (t, d) = (axis.TruePot, axis.Config.Motor.Pot);
            output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"pot {axis.Config.FullName}: true adc_at_min {t.AdcAtMin:F1} adc_at_max {t.AdcAtMax:F1} bow_counts {t.BowCounts:F1} (design {d.AdcAtMin:F0} {d.AdcAtMax:F0} {d.BowCounts:F0})"));
        }
    }
}
