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

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl bus-sim &lt;robot file&gt; --pty [--baud 3000000]</c>: presents a virtual robot's bus (every module running the real
/// firmware) on a pseudo-terminal, in real time, until interrupted; <c>--device</c> serves an existing tty instead
/// (e.g. one end of a socat pty pair).
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
        var command = new Command("bus-sim", "Expose a virtual robot's module bus on a pty (real firmware, simulated motors).");
        command.Arguments.Add(robot);
        foreach (var o in new Option[] { pty, device, seed, seconds, baud })
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

                var definition = RobotLoader.Load(parse.GetValue(robot)!.FullName);
                var simulation = new VirtualRobotOptions { Seed = parse.GetValue(seed), BaudRate = parse.GetValue(baud) };
                using var sim = new VirtualRobot(definition, new ManualTimeProvider(), simulation);
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
                    output.WriteLine($"serving {definition.Name} ({definition.Modules.Modules.Count} modules, ids {string.Join(",", definition.Modules.Modules.Select(m => m.Id))}) on serial:{terminal.SlavePath}?baud={sim.BaudRate}");
                }
                else
                {
                    error.WriteLine("give --pty or --device <tty>");
                    return 2;
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
                    $"stopped after {sim.Elapsed.TotalSeconds:F1} s simulated: {sim.SlippedTime.TotalMilliseconds:F0} ms slipped behind real time, longest stall {sim.LongestServeGap.TotalMilliseconds:F1} ms at {sim.LongestServeGapAt.TotalSeconds:F3} s (process CPU in it {sim.LongestServeGapCpu.TotalMilliseconds:F1} ms), compiled while serving {sim.MethodsCompiledWhileServing} methods ({sim.CompileTimeWhileServing.TotalMilliseconds:F1} ms), {GC.CollectionCount(0)} collections ({GC.GetTotalPauseDuration().TotalMilliseconds:F1} ms paused)"));
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
}
