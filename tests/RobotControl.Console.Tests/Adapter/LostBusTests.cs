using System.Diagnostics;
using RobotControl.Bus.Transports.Serial;
using RobotControl.Definitions.Loading;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.WebConsole.Adapter;

namespace RobotControl.WebConsole.Tests.Adapter;

/// <summary>
/// A lost bus is a fault (issue 29, class 3): the console on a pseudo-terminal whose other end goes away (the virtual
/// robot's end closed, as an unplugged adapter) trips, refuses the pedal and a jog, and its stop says the link failed.
/// </summary>
public sealed class LostBusTests
{
    private static async Task Until(Func<bool> condition, LiveSession session, string what)
    {
        var waited = Stopwatch.StartNew();
        while (!condition())
        {
            Assert.True(waited.Elapsed < TimeSpan.FromSeconds(60), $"{what}; events:\n{string.Join("\n", session.EventsAfter(0).Select(e => e.Message))}");
            await Task.Delay(20);
        }
    }

    [Fact]
    public async Task A_console_whose_bus_hangs_up_trips_refuses_motion_and_says_the_stop_could_not_be_read_back()
    {
        var robot = RobotLoader.Load(Path.Combine(ConsoleFixture.RepoRoot, "hardware", "robots", "lb-1.0.json"));
        var pty = PseudoTerminal.Create();
        using var sim = new VirtualRobot(robot, new ManualTimeProvider(), new VirtualRobotOptions { InitialJointsRad = [[0, 0, 0, 1.0, 0], [0, 0, 0, 1.5, 0]] });
        using var serving = new CancellationTokenSource();
        var server = new Thread(() => sim.Serve(pty, serving.Token)) { IsBackground = true };
        server.Start();
        try
        {
            await HangUpWhileDriving(pty, serving, server);
        }
        finally
        {
            serving.Cancel();
            server.Join(); // before the virtual robot is disposed under it
            pty.Dispose();
        }
    }

    private static async Task HangUpWhileDriving(PseudoTerminal pty, CancellationTokenSource serving, Thread server)
    {
        using var session = new LiveSession(new LiveSessionOptions { GraphPath = Path.Combine(ConsoleFixture.RepoRoot, "graphs", "teleop-lb.json"), Catalog = ConsoleFixture.Catalog(), Virtual = false, Transport = $"serial:{pty.SlavePath}?baud=1000000" });
        await Until(() => session.Status.Session == "running", session, "the session runs");
        var on = await session.TorqueAsync(true); // homing through the supervisor, motors on: PEDAL_UP
        Assert.True(on.Succeeded, on.Message);
        var pedal = await session.PedalAsync(true);
        Assert.True(pedal.Succeeded, pedal.Message);

        serving.Cancel();
        server.Join();
        pty.Dispose(); // the robot's end of the link is gone (disposing it again later does nothing)

        await Until(() => session.Status.Faults.Any(f => f.StartsWith("trip: module_silent", StringComparison.Ordinal) && f.Contains("torque_off", StringComparison.Ordinal)), session, "a module_silent trip with the motors off");
        Assert.Contains(session.EventsAfter(0), e => e.Message.Contains("hung up", StringComparison.Ordinal));
        var again = await session.PedalAsync(true);
        Assert.False(again.Succeeded);
        var jog = await session.JogAsync("right.elbow", 10);
        Assert.False(jog.Succeeded);

        var stop = session.Close().Stop!;
        Assert.False(stop.TorqueOff); // nothing can be read back over a link that is gone, and that is said
        Assert.Equal(6, stop.Unreachable.Count);
        Assert.Contains("hung up", stop.LinkFailure, StringComparison.Ordinal);
    }
}
