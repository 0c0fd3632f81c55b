using RobotControl.Bus.Client;
using RobotControl.Modules;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The bus page's commands on modules: discovery, a friendly name, the parameters (read again, or one written to FRAM
/// and read back), a reboot. Validated on the caller's (web) thread, run by the bus's owner between cycles.
/// <para>Holds no state of its own: its work writes <see cref="SessionModules"/> and <see cref="ModuleParameters"/> on the bus's owner.</para>
/// </summary>
internal sealed class ModuleCommands(BusRobot bus, CommandQueue queue, SessionEvents events, CommandChecks checks, SessionModules modules, ModuleParameters parameters)
{
    /// <summary>The longest friendly name.</summary>
    private const int MaxNameLength = 40;

    /// <inheritdoc cref="IConsoleSession.DiscoverAsync"/>
    public Task<CommandResult> DiscoverAsync() => queue.Submit(() =>
    {
        if (checks.MotorsOnRefusal("discovery") is { } refused)
        {
            return refused;
        }

        var lines = modules.Record(bus.Discover());
        parameters.QueuePresentModules(); // read on the status thread's next turns, one module per piece of work
        return CommandResult.Ok($"{modules.Found} of {bus.Controllers.Count} modules found", lines);
    });

    /// <inheritdoc cref="IConsoleSession.RenameAsync"/>
    public Task<CommandResult> RenameAsync(int controllerId, string name)
    {
        if (checks.FindController(controllerId) is not { } c)
        {
            return checks.ControllerNotFound(controllerId);
        }

        var trimmed = name?.Trim() ?? string.Empty;
        if (trimmed.Length is 0 or > MaxNameLength || trimmed.Any(char.IsControl))
        {
            return CommandChecks.Bad($"name: give 1..{MaxNameLength} printable characters");
        }

        return queue.Submit(() =>
        {
            modules.Rename(c.Id, trimmed);
            events.Add("console", $"module {c.Id} renamed \"{trimmed}\"");
            return CommandResult.Ok($"module {c.Id} is now \"{trimmed}\"");
        });
    }

    /// <inheritdoc cref="IConsoleSession.ReloadParametersAsync"/>
    public Task<CommandResult> ReloadParametersAsync(int controllerId)
    {
        if (checks.FindController(controllerId) is not { } c)
        {
            return checks.ControllerNotFound(controllerId);
        }

        return parameters.ReadAsync(c); // one parameter per gap between cycles
    }

    /// <inheritdoc cref="IConsoleSession.RebootAsync"/>
    public Task<CommandResult> RebootAsync(int controllerId)
    {
        if (checks.FindController(controllerId) is not { } c)
        {
            return checks.ControllerNotFound(controllerId);
        }

        return queue.Submit(() =>
        {
            if (checks.MotorsOnRefusal($"rebooting module {c.Id}") is { } refused)
            {
                return refused;
            }

            var reply = bus.Reboot(c.Id);
            if (reply.Outcome != ReplyOutcome.Ok)
            {
                return CommandResult.Fail(CommandOutcome.Failed, $"module {c.Id}: no reply to the reboot ({reply.Outcome})");
            }

            events.Add("console", $"module {c.Id} \"{c.Name}\" rebooted");
            return CommandResult.Ok($"module {c.Id} rebooted");
        });
    }

    /// <inheritdoc cref="IConsoleSession.WriteParameterAsync"/>
    public Task<CommandResult> WriteParameterAsync(string motor, string parameter, double value)
    {
        if (checks.FindMotor(motor) is not { } m)
        {
            return checks.MotorNotFound(motor);
        }

        if (MotorParameter.Find(parameter ?? string.Empty) is not { } p)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no parameter '{parameter}' (parameters: {string.Join(", ", MotorParameter.All.Select(x => x.Key))})"));
        }

        if (p.ToCounts(m.Config, value, out var problem) is not { } counts)
        {
            return CommandChecks.Bad($"{m.Config.FullName}: {problem}");
        }

        return queue.Submit(() =>
        {
            var (c, ch) = (m.Controller, m.Config.Channel);
            try
            {
                // The robot layer's one parameter path, as robotctl params set: checked, written, read back.
                var back = bus.WriteParameter(c.Id, p.Field.Name, ch, counts);
                parameters.Keep(c.Id, ch, p.Key, p.FromCounts(m.Config, back));
                var text = $"{m.Config.FullName}: {p.Label} = {p.FromCounts(m.Config, back):G6} {p.Unit} written to FRAM ({p.Field.Name}[{ch}] = {back}, read back)";
                events.Add("console", text);
                return CommandResult.Ok(text);
            }
            catch (Exception ex) when (ex is ArgumentException or IOException)
            {
                var message = $"{m.Config.FullName}: {p.Label} {value:G6} {p.Unit} ({counts} {p.Field.Unit}): {ex.Message}";
                events.Add("console", message);
                return CommandResult.Fail(ex is ArgumentException ? CommandOutcome.BadInput : CommandOutcome.Refused, message);
            }
        });
    }
}
