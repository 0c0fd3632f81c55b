using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The console's commands on motors: jog, setpoint, back to the loop, homing. Validated on the caller's (web) thread,
/// run by the bus's owner between cycles.
/// <para>Holds no state of its own: the motors' manual goals and positions are the robot core's, written on the bus's owner.</para>
/// </summary>
internal sealed class MotorCommands(RobotSession session, CommandQueue queue, SessionEvents events, CommandChecks checks)
{
    private BusRobot Bus => session.Robot;

    private SafetySupervisor Supervisor => session.Supervisor;

    /// <inheritdoc cref="IConsoleSession.JogAsync"/>
    public Task<CommandResult> JogAsync(string motor, double degPerS)
    {
        if (checks.FindMotor(motor) is not { } m)
        {
            return checks.MotorNotFound(motor);
        }

        var limit = m.SpeedLimitRadS * 180 / Math.PI;
        if (!double.IsFinite(degPerS) || Math.Abs(degPerS) > limit)
        {
            return CommandChecks.Bad($"{m.Config.FullName}: jog speed {degPerS} deg/s outside -{limit:F1}..{limit:F1} deg/s (the motor's speed limit)");
        }

        return queue.Submit(() =>
        {
            if (checks.MotionRefusal("jog") is { } refused)
            {
                return refused;
            }

            m.Jog(degPerS * Math.PI / 180);
            return CommandResult.Ok(degPerS == 0 ? $"{m.Config.FullName}: jog stopped, holding" : $"{m.Config.FullName}: jogging at {degPerS:G4} deg/s");
        });
    }

    /// <inheritdoc cref="IConsoleSession.SetpointAsync"/>
    public Task<CommandResult> SetpointAsync(string motor, double deg)
    {
        if (checks.FindMotor(motor) is not { } m)
        {
            return checks.MotorNotFound(motor);
        }

        var min = m.Config.OutputMinRad * 180 / Math.PI;
        var max = m.Config.OutputMaxRad * 180 / Math.PI;
        if (!double.IsFinite(deg) || deg < min || deg > max)
        {
            return CommandChecks.Bad($"{m.Config.FullName}: setpoint {deg} deg outside {min:F2}..{max:F2} deg (the joint limits)");
        }

        return queue.Submit(() =>
        {
            if (checks.MotionRefusal("a setpoint") is { } refused)
            {
                return refused;
            }

            m.SetSetpoint(deg * Math.PI / 180);
            return CommandResult.Ok($"{m.Config.FullName}: moving to {deg:G6} deg");
        });
    }

    /// <inheritdoc cref="IConsoleSession.ReleaseAsync"/>
    public Task<CommandResult> ReleaseAsync(string motor)
    {
        if (checks.FindMotor(motor) is not { } m)
        {
            return checks.MotorNotFound(motor);
        }

        return queue.Submit(() =>
        {
            m.ReleaseManual();
            return CommandResult.Ok($"{m.Config.FullName}: back under the control loop");
        });
    }

    /// <inheritdoc cref="IConsoleSession.HomeAsync"/>
    public Task<CommandResult> HomeAsync(string? motor)
    {
        RobotMotor? only = null;
        if (motor is not null && (only = checks.FindMotor(motor)) is null)
        {
            return checks.MotorNotFound(motor);
        }

        return queue.Submit(() =>
        {
            if (Supervisor.Level != RunLevel.Init)
            {
                return CommandResult.Fail(CommandOutcome.Refused, $"homing needs the motors off at run level INIT, it is {Supervisor.Level.Name()}: {(Supervisor.Level == RunLevel.EStop ? "clear faults (reset) first" : "turn torque off first")} (a driven motor must not change coordinates)");
            }

            var results = only is null ? Bus.Home() : [Bus.HomeMotor(only)];
            var lines = results.Select(r => r.ToString()).ToList();
            foreach (var line in lines)
            {
                events.Add("home", line);
            }

            var failed = results.Count(r => !r.Succeeded);
            return failed == 0
                ? CommandResult.Ok($"{results.Count} motor(s) homed", lines)
                : CommandResult.Fail(CommandOutcome.Refused, $"{failed} of {results.Count} motor(s) not homed", lines);
        });
    }

    /// <summary>The virtual robot's own output angle of <paramref name="motor"/> in degrees (tests: the simulation's truth), read on the bus's owner.</summary>
    public async Task<double> VirtualOutputDeg(string motor)
    {
        var m = checks.FindMotor(motor) ?? throw new KeyNotFoundException(motor);
        var sim = session.Simulation ?? throw new InvalidOperationException("not a virtual session");
        double value = double.NaN;
        await queue.Submit(() =>
        {
            value = sim.Axis(m.Config.Arm, m.Config.Actuator.Name).OutputAngleRad * 180 / Math.PI;
            return CommandResult.Ok("read");
        }).ConfigureAwait(false);
        return value;
    }
}
