using System.Diagnostics;
using RobotControl.Modules;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>The console's commands: validated on the caller's thread, applied on the session thread between bus cycles.</summary>
public sealed partial class LiveSession
{
    /// <summary>The longest friendly name.</summary>
    private const int MaxNameLength = 40;

    /// <inheritdoc />
    public Task<CommandResult> DiscoverAsync() => _commands.Submit(() =>
    {
        if (MotorsOnRefusal("discovery") is { } refused)
        {
            return refused;
        }

        var lines = LogDiscovery(_bus.Discover());
        foreach (var c in _bus.Controllers.Where(c => c.Present))
        {
            _pendingReads.Enqueue(c); // read on the status thread's next turns, one module per piece of work
        }

        return CommandResult.Ok($"{_found} of {_bus.Controllers.Count} modules found", lines);
    });

    /// <inheritdoc />
    public Task<CommandResult> RenameAsync(int controllerId, string name)
    {
        if (FindController(controllerId) is not { } c)
        {
            return NotFound(controllerId);
        }

        var trimmed = name?.Trim() ?? string.Empty;
        if (trimmed.Length is 0 or > MaxNameLength || trimmed.Any(char.IsControl))
        {
            return Bad($"name: give 1..{MaxNameLength} printable characters");
        }

        return _commands.Submit(() =>
        {
            _names[c.Id] = trimmed;
            _events.Add(Now, "console", $"module {c.Id} renamed \"{trimmed}\"");
            return CommandResult.Ok($"module {c.Id} is now \"{trimmed}\"");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> ReloadParametersAsync(int controllerId)
    {
        if (FindController(controllerId) is not { } c)
        {
            return NotFound(controllerId);
        }

        return _commands.Submit(() =>
        {
            ReadParameters(c);
            return CommandResult.Ok($"module {c.Id}: parameters read");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> RebootAsync(int controllerId)
    {
        if (FindController(controllerId) is not { } c)
        {
            return NotFound(controllerId);
        }

        return _commands.Submit(() =>
        {
            if (MotorsOnRefusal($"rebooting module {c.Id}") is { } refused)
            {
                return refused;
            }

            var reply = _bus.Reboot(c.Id);
            if (reply.Outcome != ReplyOutcome.Ok)
            {
                return CommandResult.Fail(CommandOutcome.Failed, $"module {c.Id}: no reply to the reboot ({reply.Outcome})");
            }

            _events.Add(Now, "console", $"module {c.Id} \"{c.Name}\" rebooted");
            return CommandResult.Ok($"module {c.Id} rebooted");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value)
    {
        if (FindMotor(motor) is not { } m)
        {
            return MotorNotFound(motor);
        }

        if (MotorParameter.Find(parameter ?? string.Empty) is not { } p)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no parameter '{parameter}' (parameters: {string.Join(", ", MotorParameter.All.Select(x => x.Key))})"));
        }

        if (p.ToCounts(m.Config, value, out var problem) is not { } counts)
        {
            return Bad($"{m.Config.FullName}: {problem}");
        }

        return _commands.Submit(() =>
        {
            var (c, ch) = (m.Controller, m.Config.Channel);
            try
            {
                // The robot layer's one parameter path, as robotctl params set: checked, written, read back.
                var back = _bus.WriteParameter(c.Id, p.Field.Name, ch, counts);
                _parameters[(c.Id, ch, p.Key)] = p.FromCounts(m.Config, back);
                var text = $"{m.Config.FullName}: {p.Label} = {p.FromCounts(m.Config, back):G6} {p.Unit} written to FRAM ({p.Field.Name}[{ch}] = {back}, read back)";
                _events.Add(Now, "console", text);
                return CommandResult.Ok(text);
            }
            catch (Exception ex) when (ex is ArgumentException or IOException)
            {
                var message = $"{m.Config.FullName}: {p.Label} {value:G6} {p.Unit} ({counts} {p.Field.Unit}): {ex.Message}";
                _events.Add(Now, "console", message);
                return CommandResult.Fail(ex is ArgumentException ? CommandOutcome.BadInput : CommandOutcome.Refused, message);
            }
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> JogAsync(string motor, double degPerS)
    {
        if (FindMotor(motor) is not { } m)
        {
            return MotorNotFound(motor);
        }

        var limit = m.SpeedLimitRadS * 180 / Math.PI;
        if (!double.IsFinite(degPerS) || Math.Abs(degPerS) > limit)
        {
            return Bad($"{m.Config.FullName}: jog speed {degPerS} deg/s outside -{limit:F1}..{limit:F1} deg/s (the motor's speed limit)");
        }

        return _commands.Submit(() =>
        {
            if (MotionRefusal("jog") is { } refused)
            {
                return refused;
            }

            m.Jog(degPerS * Math.PI / 180);
            return CommandResult.Ok(degPerS == 0 ? $"{m.Config.FullName}: jog stopped, holding" : $"{m.Config.FullName}: jogging at {degPerS:G4} deg/s");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> SetpointAsync(string motor, double deg)
    {
        if (FindMotor(motor) is not { } m)
        {
            return MotorNotFound(motor);
        }

        var min = m.Config.OutputMinRad * 180 / Math.PI;
        var max = m.Config.OutputMaxRad * 180 / Math.PI;
        if (!double.IsFinite(deg) || deg < min || deg > max)
        {
            return Bad($"{m.Config.FullName}: setpoint {deg} deg outside {min:F2}..{max:F2} deg (the joint limits)");
        }

        return _commands.Submit(() =>
        {
            if (MotionRefusal("a setpoint") is { } refused)
            {
                return refused;
            }

            m.SetSetpoint(deg * Math.PI / 180);
            return CommandResult.Ok($"{m.Config.FullName}: moving to {deg:G6} deg");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> ReleaseAsync(string motor)
    {
        if (FindMotor(motor) is not { } m)
        {
            return MotorNotFound(motor);
        }

        return _commands.Submit(() =>
        {
            m.ReleaseManual();
            return CommandResult.Ok($"{m.Config.FullName}: back under the control loop");
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> TorqueAsync(bool on) => _commands.Submit(() =>
    {
        if (!on)
        {
            _supervisor.MotorsOff("console");
            LogSupervisor();
            return CommandResult.Ok($"motors off (run level {_supervisor.Level.Name()})");
        }

        if (_supervisor.Level is RunLevel.PedalUp or RunLevel.PedalDown)
        {
            return CommandResult.Ok($"the motors are on already (run level {_supervisor.Level.Name()})");
        }

        if (_supervisor.Level == RunLevel.EStop)
        {
            return CommandResult.Fail(CommandOutcome.Refused, "the run level is E_STOP: clear faults (an operator reset) first, then turn torque on");
        }

        try
        {
            var homed = _supervisor.Home("console");
            LogSupervisor();
            return CommandResult.Ok(homed.Count == 0 ? "motors on, holding (run level PEDAL_UP)" : $"{homed.Count} motors homed; motors on, holding (run level PEDAL_UP)");
        }
        catch (InvalidOperationException ex)
        {
            LogSupervisor();
            return CommandResult.Fail(CommandOutcome.Refused, $"torque on: {ex.Message}");
        }
    });

    /// <inheritdoc />
    public Task<CommandResult> PedalAsync(bool down) => _commands.Submit(() =>
    {
        if (!down)
        {
            _supervisor.PedalUp("console");
            LogSupervisor();
            return CommandResult.Ok($"pedal up: holding (run level {_supervisor.Level.Name()})");
        }

        try
        {
            _supervisor.PedalDown("console");
        }
        catch (InvalidOperationException ex)
        {
            return CommandResult.Fail(CommandOutcome.Refused, $"{ex.Message}: turn torque on first");
        }

        LogSupervisor();
        return CommandResult.Ok("pedal down: the arms follow the graph and the console's jogs (run level PEDAL_DOWN)");
    });

    /// <summary>How long an emergency stop's caller waits to see the run level at E_STOP before it is told it is not yet.</summary>
    private static readonly TimeSpan EmergencyStopConfirmation = TimeSpan.FromSeconds(1);

    /// <inheritdoc />
    /// <remarks>
    /// Not a queued command: the supervisor's emergency stop is lock-free from this thread and overtakes any queued
    /// work; the result says when the run level is E_STOP (the hold or the motors off is then on the wire).
    /// </remarks>
    public async Task<CommandResult> EmergencyStopAsync()
    {
        _supervisor.EmergencyStop("console", "operator's emergency stop on the console");
        var waited = Stopwatch.StartNew();
        while (_supervisor.Level != RunLevel.EStop && waited.Elapsed < EmergencyStopConfirmation)
        {
            await Task.Delay(1).ConfigureAwait(false);
        }

        return _supervisor.Level == RunLevel.EStop
            ? CommandResult.Ok($"emergency stop: run level {_supervisor.Level.Name()}; clear faults to reset")
            : CommandResult.Fail(CommandOutcome.Failed, $"emergency stop asked for; the run level is still {_supervisor.Level.Name()} after {EmergencyStopConfirmation.TotalSeconds:0} s: the bus cycle is not running ({_state})");
    }

    /// <inheritdoc />
    public Task<CommandResult> HomeAsync(string? motor)
    {
        RobotMotor? only = null;
        if (motor is not null && (only = FindMotor(motor)) is null)
        {
            return MotorNotFound(motor);
        }

        return _commands.Submit(() =>
        {
            if (_supervisor.Level != RunLevel.Init)
            {
                return CommandResult.Fail(CommandOutcome.Refused, $"homing needs the motors off at run level INIT, it is {_supervisor.Level.Name()}: {(_supervisor.Level == RunLevel.EStop ? "clear faults (reset) first" : "turn torque off first")} (a driven motor must not change coordinates)");
            }

            var results = only is null ? _bus.Home() : [_bus.HomeMotor(only)];
            var lines = results.Select(r => r.ToString()).ToList();
            foreach (var line in lines)
            {
                _events.Add(Now, "home", line);
            }

            var failed = results.Count(r => !r.Succeeded);
            return failed == 0
                ? CommandResult.Ok($"{results.Count} motor(s) homed", lines)
                : CommandResult.Fail(CommandOutcome.Refused, $"{failed} of {results.Count} motor(s) not homed", lines);
        });
    }

    /// <inheritdoc />
    public Task<CommandResult> ClearFaultsAsync() => _commands.Submit(() =>
    {
        _bus.ClearFaults();
        if (_supervisor.Level == RunLevel.EStop)
        {
            _supervisor.Reset("console");
            LogSupervisor();
            _events.Add(Now, "console", "faults cleared; E_STOP reset to INIT");
            return CommandResult.Ok("faults cleared; run level INIT: turn torque on to home and hold");
        }

        _events.Add(Now, "console", "faults cleared");
        return CommandResult.Ok("faults cleared");
    });

    /// <summary>The virtual robot's own output angle of <paramref name="motor"/> in degrees (tests: the simulation's truth), read on the session thread.</summary>
    internal async Task<double> VirtualOutputDeg(string motor)
    {
        var m = FindMotor(motor) ?? throw new KeyNotFoundException(motor);
        var sim = _session.Simulation ?? throw new InvalidOperationException("not a virtual session");
        double value = double.NaN;
        await _commands.Submit(() =>
        {
            value = sim.Axis(m.Config.Arm, m.Config.Actuator.Name).OutputAngleRad * 180 / Math.PI;
            return CommandResult.Ok("read");
        }).ConfigureAwait(false);
        return value;
    }

    /// <summary>A refusal when the motors are on (run level PEDAL_UP or PEDAL_DOWN), else null.</summary>
    private CommandResult? MotorsOnRefusal(string action) => TorqueOn
        ? CommandResult.Fail(CommandOutcome.Refused, $"{action} needs the motors off, the run level is {_supervisor.Level.Name()}: turn torque off first")
        : null;

    /// <summary>A refusal unless the run level lets the console move the robot (PEDAL_DOWN), else null.</summary>
    private CommandResult? MotionRefusal(string action) => _supervisor.Level == RunLevel.PedalDown
        ? null
        : CommandResult.Fail(CommandOutcome.Refused, $"{action} moves the robot: it needs the run level PEDAL_DOWN, it is {_supervisor.Level.Name()} ({(_supervisor.Level == RunLevel.PedalUp ? "press the pedal" : "turn torque on, then press the pedal")})");

    private static Task<CommandResult> Bad(string message) => Task.FromResult(CommandResult.Fail(CommandOutcome.BadInput, message));

    private Task<CommandResult> NotFound(int id) =>
        Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no controller {id} (controllers: {string.Join(", ", _bus.Controllers.Select(c => c.Id))})"));

    private Task<CommandResult> MotorNotFound(string? name) =>
        Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no motor '{name}' (motors: {string.Join(", ", _bus.Motors.Select(m => m.Config.FullName))})"));

    private RobotController? FindController(int id) => _bus.Controllers.FirstOrDefault(c => c.Id == id);

    private RobotMotor? FindMotor(string? name) => _bus.Motors.FirstOrDefault(m => m.Config.FullName == name);
}
