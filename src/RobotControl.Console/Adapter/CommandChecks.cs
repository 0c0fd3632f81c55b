using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// What the console's commands check: the module or motor named (on the caller's thread, before anything is queued)
/// and whether the run level allows the command (on the bus's owner, when the command runs).
/// <para>Holds no state of its own.</para>
/// </summary>
internal sealed class CommandChecks(BusRobot bus, SafetySupervisor supervisor)
{
    /// <summary>A command refused for bad input; nothing is queued.</summary>
    public static Task<CommandResult> Bad(string message) => Task.FromResult(CommandResult.Fail(CommandOutcome.BadInput, message));

    /// <summary>The module <paramref name="id"/>, or null.</summary>
    public RobotController? FindController(int id) => bus.Controllers.FirstOrDefault(c => c.Id == id);

    /// <summary>The motor of full name <paramref name="name"/>, or null.</summary>
    public RobotMotor? FindMotor(string? name) => bus.Motors.FirstOrDefault(m => m.Config.FullName == name);

    /// <summary>No module <paramref name="id"/>: the modules there are.</summary>
    public Task<CommandResult> ControllerNotFound(int id) =>
        Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no controller {id} (controllers: {string.Join(", ", bus.Controllers.Select(c => c.Id))})"));

    /// <summary>No motor <paramref name="name"/>: the motors there are.</summary>
    public Task<CommandResult> MotorNotFound(string? name) =>
        Task.FromResult(CommandResult.Fail(CommandOutcome.NotFound, $"no motor '{name}' (motors: {string.Join(", ", bus.Motors.Select(m => m.Config.FullName))})"));

    /// <summary>A refusal when the motors are on (run level PEDAL_UP or PEDAL_DOWN), else null.</summary>
    public CommandResult? MotorsOnRefusal(string action) => StatusPublisher.TorqueOn(bus)
        ? CommandResult.Fail(CommandOutcome.Refused, $"{action} needs the motors off, the run level is {supervisor.Level.Name()}: turn torque off first")
        : null;

    /// <summary>A refusal unless the run level lets the console move the robot (PEDAL_DOWN), else null.</summary>
    public CommandResult? MotionRefusal(string action) => supervisor.Level == RunLevel.PedalDown
        ? null
        : CommandResult.Fail(CommandOutcome.Refused, $"{action} moves the robot: it needs the run level PEDAL_DOWN, it is {supervisor.Level.Name()} ({(supervisor.Level == RunLevel.PedalUp ? "press the pedal" : "turn torque on, then press the pedal")})");
}
