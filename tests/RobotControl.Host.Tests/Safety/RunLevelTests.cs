using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Host.Session;
using RobotControl.Robot.Control.States;
using RobotControl.Robot.States;

namespace RobotControl.Host.Tests.Safety;

public sealed class RunLevelTests
{
    [Fact]
    public void Init_homing_pedal_up_pedal_down_trip_estop_reset_init_and_homing_again()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        supervisor.PedalDown("pedal");
        session.RunVirtual(200);
        Assert.Equal(RunLevel.PedalDown, supervisor.Level);

        var elbow = session.Simulation!.Axes.Single(a => a.Config.FullName == "right.elbow");
        elbow.CurrentSenseOffsetA = 2 * elbow.Config.Motor.CurrentLimitA;
        session.RunVirtual(400);
        Assert.Equal(RunLevel.EStop, supervisor.Level);
        Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("pedal")); // no way out but a reset

        elbow.CurrentSenseOffsetA = 0;
        supervisor.Reset("operator");
        Assert.Equal(RunLevel.Init, supervisor.Level);
        Assert.NotEqual(RobotState.Enabled, session.Robot.State);
        var homed = supervisor.Home("operator");
        Assert.Equal(session.Robot.Motors.Count, homed.Count); // after a reset every motor is homed again
        Assert.All(homed, r => Assert.True(r.Succeeded, r.Detail));
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);

        var levels = supervisor.History.Select(h => (h.From, h.To)).ToList();
        Assert.Equal(
            [(RunLevel.Init, RunLevel.Homing), (RunLevel.Homing, RunLevel.PedalUp), (RunLevel.PedalUp, RunLevel.PedalDown), (RunLevel.PedalDown, RunLevel.EStop),
             (RunLevel.EStop, RunLevel.Init), (RunLevel.Init, RunLevel.Homing), (RunLevel.Homing, RunLevel.PedalUp)],
            levels);
        Assert.All(supervisor.History, h => Assert.False(string.IsNullOrWhiteSpace(h.Reason)));
        Assert.Equal("supervisor", supervisor.History[3].Source);
        Assert.Equal("operator", supervisor.History[4].Source);
    }

    [Fact]
    public void An_emergency_stop_asked_for_from_another_thread_is_taken_in_the_next_cycle_and_holds()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        supervisor.PedalDown("pedal");
        session.RunVirtual(100);
        var asker = new Thread(() => supervisor.EmergencyStop("cli", "E-STOP key on the command line"));
        asker.Start();
        asker.Join();
        Assert.Equal(RunLevel.PedalDown, supervisor.Level); // nothing happens off the bus thread
        session.RunVirtual(session.Loop.TickCount + 3); // the next bus cycle: one lasts 1 to 2.6 ms of the 1 ms ticks
        Assert.Equal(RunLevel.EStop, supervisor.Level);
        var stop = supervisor.History[^1];
        Assert.Equal(("cli", "E-STOP key on the command line"), (stop.Source, stop.Reason));
        var trip = Assert.Single(supervisor.Trips);
        Assert.Equal((SafetyCheck.Operator, SafeState.Hold), (trip.Check, trip.Action));
        Assert.Equal(RobotState.Enabled, session.Robot.State); // hold: motors on, goals frozen
        session.RunVirtual(session.Loop.TickCount + 100);
        Assert.Single(supervisor.Trips); // taken once
        Assert.Throws<ArgumentException>(() => supervisor.EmergencyStop(" ", "x"));
    }

    [Fact]
    public void Nothing_moves_at_pedal_up_although_the_graph_commands_motion()
    {
        var goal = RobotControl.Bus.Protocol.ControlTable.Firmware["goal_position"];
        GoalFrameSpy? spy = null;
        using var session = RobotSession.Open(
            new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json"), WrapLink = (link, clock) => spy = new GoalFrameSpy(link, clock, goal.At(0), goal.Stride) },
            TestPlugins.Catalog());
        var before = spy!.Frames.Count;
        session.RunVirtual(1000);
        Assert.Equal(RunLevel.PedalUp, session.Supervisor.Level);
        var frames = spy.Frames.Skip(before).ToList();
        Assert.True(frames.Count > 100);
        Assert.All(frames, f => Assert.All(f.Goals, g => Assert.Equal(frames[0].Goals[g.Key], g.Value)));
        Assert.True(session.Node.CommandedThisTick(0)); // the graph did command the right arm
        Assert.Empty(session.Supervisor.Trips);
    }

    [Fact]
    public void Motors_off_goes_to_init_and_homing_turns_them_on_again_without_rehoming()
    {
        using var session = RobotSession.Open(new SessionOptions { GraphPath = Graphs.Path("teleop-lb.json") }, TestPlugins.Catalog());
        var supervisor = session.Supervisor;
        supervisor.PedalDown("pedal");
        session.RunVirtual(100);
        supervisor.MotorsOff("console");
        Assert.Equal(RunLevel.Init, supervisor.Level);
        Assert.NotEqual(RobotState.Enabled, session.Robot.State);
        Assert.Throws<InvalidOperationException>(() => supervisor.PedalDown("pedal"));
        session.RunVirtual(200);

        // With the motors off, long bus work between cycles (a rediscovery, 30 ms of parameter reads) trips nothing.
        session.Robot.Discover();
        var busClock = session.Connection.VirtualClock!;
        var before = busClock.GetTimestamp();
        while (busClock.GetElapsedTime(before) < TimeSpan.FromMilliseconds(30))
        {
            session.Robot.ReadParameter(session.Robot.Controllers[0].Id, "kp", 0);
        }

        session.RunVirtual(400);
        Assert.Empty(supervisor.Trips);

        busClock.Advance(TimeSpan.FromMilliseconds(30)); // the cycle after power-up comes late: not a stall of a powered robot
        Assert.Empty(supervisor.Home("console")); // nothing in doubt: motors on without homing
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        Assert.Equal(RobotState.Enabled, session.Robot.State);
        session.RunVirtual(600);
        Assert.Empty(supervisor.Trips);
        Assert.Equal(RunLevel.PedalUp, supervisor.Level);
        Assert.Equal(
            [(RunLevel.PedalDown, RunLevel.PedalUp), (RunLevel.PedalUp, RunLevel.Init), (RunLevel.Init, RunLevel.Homing), (RunLevel.Homing, RunLevel.PedalUp)],
            supervisor.History.Skip(3).Select(h => (h.From, h.To)).ToList());
    }

    [Fact]
    public void The_run_levels_are_declared_once_with_the_levels_that_may_follow_and_nothing_leaves_e_stop_but_init()
    {
        RunLevel[] all = Enum.GetValues<RunLevel>();
        var follows = new Dictionary<RunLevel, RunLevel[]>
        {
            [RunLevel.EStop] = [RunLevel.Init],
            [RunLevel.Init] = [RunLevel.Homing, RunLevel.EStop],
            [RunLevel.Homing] = [RunLevel.PedalUp, RunLevel.Init, RunLevel.EStop],
            [RunLevel.PedalUp] = [RunLevel.PedalDown, RunLevel.Init, RunLevel.EStop],
            [RunLevel.PedalDown] = [RunLevel.PedalUp, RunLevel.EStop],
        };
        foreach (var from in all)
        {
            foreach (var to in all.Where(l => l != from))
            {
                var machine = RunLevels.NewMachine(TimeProvider.System);
                Assert.True(PathTo(machine, from));
                var historyBefore = machine.History.Count;
                if (follows[from].Contains(to))
                {
                    Assert.True(machine.MoveTo(to, "test", $"{from.Name()} to {to.Name()}"));
                    Assert.Equal(to, machine.Current);
                }
                else
                {
                    Assert.Throws<InvalidOperationException>(() => machine.MoveTo(to, "test", "not declared"));
                    Assert.Equal((from, historyBefore), (machine.Current, machine.History.Count));
                }
            }
        }

        var levels = RunLevels.NewMachine(TimeProvider.System);
        var error = Assert.Throws<InvalidOperationException>(() => levels.MoveTo(RunLevel.PedalDown, "pedal", "test"));
        Assert.Equal("the run level cannot go from INIT to PEDAL_DOWN (pedal: test); from INIT it may go to HOMING, E_STOP", error.Message);
        Assert.Equal(RunLevel.Init, levels.Current);
    }

    /// <summary>Takes a fresh machine (at INIT) to <paramref name="level"/> through declared moves.</summary>
    private static bool PathTo(StateMachine<RunLevel> machine, RunLevel level)
    {
        RunLevel[] path = level switch
        {
            RunLevel.EStop => [RunLevel.EStop],
            RunLevel.Init => [],
            RunLevel.Homing => [RunLevel.Homing],
            RunLevel.PedalUp => [RunLevel.Homing, RunLevel.PedalUp],
            _ => [RunLevel.Homing, RunLevel.PedalUp, RunLevel.PedalDown],
        };
        foreach (var l in path)
        {
            machine.MoveTo(l, "test", "on the way");
        }

        return machine.Current == level;
    }
}
