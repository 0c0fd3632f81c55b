using RobotControl.Bus.Protocol;
using RobotControl.Host.Harness;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Robot.States;

namespace RobotControl.Host.Tests.Harness;

/// <summary>A robot that faults mid-run stops the run; the stop switches torque off and reads every module back.</summary>
public sealed class FaultStopTests
{
    private static string Graph() => Graphs.Path("teleop-lb.json");

    /// <summary>Arms module 1's bus watchdog at 1 ms (hold) and 2 ms (torque off) and lets 20 ms of bus time pass in silence: it trips.</summary>
    private static void TripWatchdog(RobotSession session)
    {
        var watchdog = ControlTable.Firmware["bus_watchdog"];
        var watchdogOff = ControlTable.Firmware["bus_watchdog_off"];
        Assert.True(session.Robot.Client.Write(1, watchdog.At(0), [1, 0]).Succeeded); // stage 1 first: stage 2 must stay after it
        Assert.True(session.Robot.Client.Write(1, watchdogOff.At(0), [2, 0]).Succeeded);
        Span<byte> idle = stackalloc byte[16];
        _ = session.Robot.Client.Link.Read(idle, TimeSpan.FromMilliseconds(20));
    }

    [Fact]
    public void A_tripped_watchdog_stops_the_run_and_the_stop_leaves_every_module_torque_off()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graph() }, TestPlugins.Catalog());
        var stop = new FaultStop(session.Robot, continueOnFault: false, CancellationToken.None, session.Supervisor);
        session.RunVirtual(200, stopWhen: stop.ShouldStop);
        Assert.Null(stop.Fault);
        Assert.Equal(200, session.Loop.TickCount);

        TripWatchdog(session);
        session.RunVirtual(2200, stopWhen: stop.ShouldStop);
        Assert.True(session.Loop.TickCount < 1200, $"ran {session.Loop.TickCount} ticks after the trip");
        Assert.Contains("watchdog", stop.Fault, StringComparison.Ordinal);
        Assert.False(stop.Interrupted);
        Assert.NotEqual(RobotState.Enabled, session.Robot.State); // the supervisor's module_fault trip switched the motors off
        Assert.Equal(RunLevel.EStop, session.Supervisor.Level);

        var check = session.Stop();
        Assert.True(check.TorqueOff, string.Join("; ", check.TorqueOn.Concat(check.Unreachable)));
        Assert.Equal(6, check.Modules);
        Assert.Contains(check.LatchedErrors, e => e.StartsWith("1 ", StringComparison.Ordinal) && e.Contains("bus_watchdog", StringComparison.Ordinal));
        Assert.Same(check, session.Stop()); // checked once
    }

    [Fact]
    public void With_continue_on_fault_the_run_goes_on_and_a_stop_request_ends_it()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graph() }, TestPlugins.Catalog());
        using var cancel = new CancellationTokenSource();
        var stop = new FaultStop(session.Robot, continueOnFault: true, cancel.Token, session.Supervisor);
        TripWatchdog(session);
        session.RunVirtual(500, stopWhen: stop.ShouldStop);
        Assert.Equal(500, session.Loop.TickCount);
        Assert.Null(stop.Fault);

        cancel.Cancel();
        session.RunVirtual(1000, stopWhen: stop.ShouldStop);
        Assert.True(stop.Interrupted);
        Assert.True(session.Loop.TickCount < 520);
    }
}
