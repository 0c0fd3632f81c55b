using System.Reflection;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Tests.Session;

public sealed class RobotlessSessionTests
{
    [Fact]
    public async Task Every_robot_command_of_the_console_is_refused_with_the_modes_sentence_and_the_emergency_stop_is_not()
    {
        using var session = new NoRobot();
        var commands = typeof(IConsoleSession).GetMethods()
            .Where(m => m.ReturnType == typeof(Task<CommandResult>) && m.Name != nameof(IConsoleSession.EmergencyStopAsync))
            .ToList();
        Assert.True(commands.Count >= 14, $"{commands.Count} commands found"); // discovery, rename, reload, reboot, parameter, jog, setpoint, release, torque, pedal, home, clear, scale, record

        foreach (var command in commands)
        {
            var args = command.GetParameters().Select(Sample).ToArray();
            var result = await (Task<CommandResult>)command.Invoke(session, args)!;
            Assert.True(result is { Outcome: CommandOutcome.Refused, Message: NoRobot.Sentence }, $"{command.Name}: {result.Outcome} \"{result.Message}\"");
        }

        Assert.Equal(CommandOutcome.Ok, (await session.EmergencyStopAsync()).Outcome);
        Assert.Empty(session.Controllers);
        Assert.Null(session.RecordingFile);
    }

    private static object? Sample(ParameterInfo p) =>
        p.ParameterType == typeof(string) ? "right.elbow"
        : p.ParameterType == typeof(int) ? 2
        : p.ParameterType == typeof(double) ? 1.0
        : p.ParameterType == typeof(bool) ? true
        : null;

    private sealed class NoRobot() : RobotlessSession(Sentence)
    {
        public const string Sentence = "no robot here: test mode";

        public override SessionStatus Status => throw new NotSupportedException();

        public override SignalRing Signals { get; } = new([], [], 2);

        public override RobotModelView Model { get; } = new(string.Empty, []);

        public override SurgeonView Surgeon { get; } = new([], [], []);

        public override WorkspaceView Workspace { get; } = new([]);

        public override IReadOnlyList<EventEntry> EventsAfter(long after) => [];

        public override Task<CommandResult> EmergencyStopAsync() => Task.FromResult(CommandResult.Ok("no motors"));

        public override SessionEnd Close() => throw new NotSupportedException();
    }
}
