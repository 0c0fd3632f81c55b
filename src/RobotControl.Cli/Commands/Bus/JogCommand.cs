using System.CommandLine;
using System.Globalization;
using RobotControl.Cli.Options;
using RobotControl.Robot.Control;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// <c>robotctl jog &lt;transport&gt; --motor right.elbow --speed-deg-s 10 --duration-s 1</c>: turns the motors on,
/// jogs one motor (its axis output) for a while, prints where it went, turns the motors off. Exit 1 when a module is
/// missing, unknown or mismatched, or the robot reports a fault.
/// </summary>
internal sealed class JogCommand : ICliCommand
{
    private const double Deg = Math.PI / 180;

    /// <inheritdoc />
    public Command Build()
    {
        var motor = new Option<string>("--motor") { Description = "arm.joint, e.g. right.elbow or left.tool_open_close", Required = true };
        var speed = CliOption.Number("--speed-deg-s", "Axis output speed, deg/s (limited to the motor's speed limit)", -720.0, 720.0, 10.0);
        var duration = CliOption.Number("--duration-s", "How long to jog, s", 0.001, 600.0, 1.0);
        var command = new Command("jog", "Jog one motor at a speed for a time, then stop and report.");
        var busOptions = new BusOptions(command);
        foreach (var o in new Option[] { motor, speed, duration })
        {
            command.Options.Add(o);
        }

        command.SetAction(parse =>
        {
            var output = parse.InvocationConfiguration.Output;
            return busOptions.Run(parse, session =>
            {
                var bus = session.RequireRobot();
                var report = bus.Discover();
                var m = bus.Motor(parse.GetValue(motor)!);
                if (!m.Controller.Present)
                {
                    throw new IOException($"{m}: its module does not answer");
                }

                bus.EnableTorque(true);
                var start = m.PositionRad;
                m.Jog(parse.GetValue(speed) * Deg);
                bus.RunFor(TimeSpan.FromSeconds(parse.GetValue(duration)));
                m.Jog(0);
                bus.RunFor(TimeSpan.FromMilliseconds(300));
                bus.EnableTorque(false);
                output.WriteLine(string.Create(CultureInfo.InvariantCulture, $"{m.Config.FullName}: {start / Deg:F2} deg -> {m.PositionRad / Deg:F2} deg, current {m.CurrentA * 1000:F1} mA, faults {bus.Faults}"));
                foreach (var e in bus.Events.History())
                {
                    output.WriteLine(e);
                }

                // Anything short of every module as configured and no fault is a failed jog.
                return report.AllAsConfigured && bus.Faults == RobotFaults.None ? 0 : 1;
            });
        });
        return command;
    }
}
