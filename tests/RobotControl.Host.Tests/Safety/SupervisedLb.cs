using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Host.Tests.Safety;

/// <summary>
/// A safety supervisor on a virtual LB-1.0 without a graph: the test plays the control loop (its ticks, the input
/// ages and speeds, the pedals) and runs the bus cycles on its own thread, all on the bus's manual clock. The modules
/// are the real firmware.
/// </summary>
internal sealed class SupervisedLb : IDisposable
{
    /// <summary>The loop period the supervisor is given (the stall limit is 10 of them: 10 ms).</summary>
    public static readonly TimeSpan LoopPeriod = TimeSpan.FromMilliseconds(1);

    /// <summary>A supervised LB at PEDAL_DOWN (<paramref name="limits"/>: default the robot file's), 5 cycles on.</summary>
    public static SupervisedLb AtPedalDown(SafetyLimits? limits = null)
    {
        var lb = new SupervisedLb(limits);
        lb.Supervisor.PedalDown("console");
        lb.Cycles(5);
        return lb;
    }

    /// <summary>The LB's robot-file safety section.</summary>
    public static SafetyLimits FileLimits => ShippedRobots.Lb.Safety;

    /// <summary>The robot file's limits with <paramref name="check"/>'s safe state <paramref name="state"/>.</summary>
    public static SafetyLimits WithSafeState(SafetyCheck check, SafeState state) =>
        FileLimits with { SafeStates = new Dictionary<SafetyCheck, SafeState>(SafetyLimits.DefaultSafeStates) { [check] = state } };

    /// <summary>Discovered, supervised with <paramref name="limits"/> (default: the robot file's), and with <paramref name="home"/> homed to PEDAL_UP.</summary>
    public SupervisedLb(SafetyLimits? limits = null, bool home = true, VirtualRobotOptions? sim = null, RobotDefinition? hostView = null)
    {
        Lb = new VirtualLb(sim, hostView, start: false);
        Robot.Discover();
        Supervisor = new SafetySupervisor(Robot, limits ?? FileLimits, LoopPeriod);
        if (home)
        {
            Supervisor.Home("test");
        }
    }

    public VirtualLb Lb { get; }

    public BusRobot Robot => Lb.Robot;

    public VirtualRobot Sim => Lb.Sim;

    public ManualTimeProvider Clock => Lb.Clock;

    public SafetySupervisor Supervisor { get; }

    /// <summary>Seconds on the bus clock since the supervisor's origin.</summary>
    public double Now => Supervisor.Seconds(Clock.GetTimestamp());

    /// <summary>The last run-level change.</summary>
    public (RunLevel From, RunLevel To, string Source, string Reason) LastMove =>
        Supervisor.History[^1] is var h ? (h.From, h.To, h.Source, h.Reason) : default;

    /// <summary>The motor <paramref name="fullName"/> (e.g. <c>right.elbow</c>) and its virtual axis.</summary>
    public (RobotMotor Motor, VirtualAxis Axis) Motor(string fullName) =>
        (Robot.Motor(fullName), Sim.Axes.Single(a => a.Config.FullName == fullName));

    /// <summary>
    /// Runs <paramref name="count"/> bus cycles, this thread owning the bus as the bus thread does (a stop from the
    /// check is taken at once); with <paramref name="ticking"/> the loop ticks before each (it is alive).
    /// </summary>
    public void Cycles(int count, bool ticking = true)
    {
        using var own = Robot.OwnBus();
        for (var i = 0; i < count; i++)
        {
            if (ticking)
            {
                Supervisor.ReportTick();
            }

            Robot.RunCycle();
        }
    }

    /// <summary>The operator's emergency stop on the bus's owner (a console command between cycles): E_STOP at once.</summary>
    public void StopNow()
    {
        using (Robot.OwnBus())
        {
            Supervisor.EmergencyStop("console", "stop");
        }

        Assert.Equal(RunLevel.EStop, Supervisor.Level);
    }

    /// <summary>The graph's pedal is lifted for a cycle, then pressed for one (a press the supervisor sees as an edge).</summary>
    public void PressPedal()
    {
        Supervisor.ReportPedal(false);
        Cycles(1);
        Supervisor.ReportPedal(true);
        Cycles(1);
    }

    /// <summary>Runs bus cycles (the loop ticking) until <paramref name="duration"/> has passed on the bus clock.</summary>
    public void CyclesFor(TimeSpan duration, bool ticking = true)
    {
        var start = Clock.GetTimestamp();
        while (Clock.GetElapsedTime(start) < duration)
        {
            Cycles(1, ticking);
        }
    }

    /// <summary>Runs bus cycles (the loop ticking) until <paramref name="done"/> or, failing the test, <paramref name="within"/> of bus time.</summary>
    public void CyclesUntil(Func<bool> done, TimeSpan within, bool ticking = true)
    {
        var start = Clock.GetTimestamp();
        while (!done())
        {
            Assert.True(Clock.GetElapsedTime(start) < within, $"not within {within.TotalMilliseconds} ms of bus time");
            Cycles(1, ticking);
        }
    }

    /// <summary>
    /// Calls <paramref name="command"/> (an operator's, queued for the bus) on another thread while this thread owns the
    /// bus and runs cycles until the command has run between two of them (at most 1000: then it fails, the bus released);
    /// rethrows what it threw.
    /// </summary>
    public void FromAnotherThread(Action command)
    {
        Exception? error = null;
        var caller = new Thread(() =>
        {
            try
            {
                command();
            }
            catch (Exception ex)
            {
                error = ex;
            }
        });
        using (Robot.OwnBus())
        {
            var ran = Robot.Slot.Ran;
            caller.Start();
            SpinWait.SpinUntil(() => Robot.Slot.Pending > 0 || !caller.IsAlive);
            for (var cycles = 0; caller.IsAlive && Robot.Slot.Ran == ran && cycles < 1000; cycles++)
            {
                Cycles(1); // the command runs between two cycles (not while an emergency stop is on its way)
            }
        }

        caller.Join();
        if (error is not null)
        {
            System.Runtime.ExceptionServices.ExceptionDispatchInfo.Throw(error);
        }
    }

    /// <summary>The host says nothing for <paramref name="duration"/> (the bus clock moves on, the modules run).</summary>
    public void Stall(TimeSpan duration) => Sim.Advance(duration);

    public void Dispose() => Lb.Dispose();
}
