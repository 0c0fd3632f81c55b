using RobotControl.Definitions.Model;
using RobotControl.Robot.Bus;
using RobotControl.Robot.Events;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>A virtual LB-1.0 and the robot layer on it with a <see cref="TapLink"/> between them.</summary>
internal sealed class TappedLb : IDisposable
{
    private TapLink? _tap;
    private int _checks;

    public TappedLb(bool start = true, BusRobotOptions? options = null, VirtualRobotOptions? sim = null, RobotDefinition? hostView = null, Action<TapLink>? beforeStart = null, TimeSpan clockAt = default)
    {
        Lb = new VirtualLb(sim, hostView, start: false, options, link: inner => _tap = new TapLink(inner), clockAt);
        Robot.CycleCheck = new CountingCheck(() => Interlocked.Increment(ref _checks));
        beforeStart?.Invoke(Tap);
        if (start)
        {
            Discovery = Robot.Discover();
            Robot.EnableTorque(true);
        }
    }

    public VirtualLb Lb { get; }

    public TapLink Tap => _tap!;

    public BusRobot Robot => Lb.Robot;

    public VirtualRobot Sim => Lb.Sim;

    public ManualTimeProvider Clock => Lb.Clock;

    public DiscoveryReport? Discovery { get; }

    /// <summary>How many times the robot ran its per-cycle check (<see cref="BusRobot.CycleCheck"/>).</summary>
    public int Checks => Volatile.Read(ref _checks);

    /// <summary>The events of kind <typeparamref name="T"/> published so far, oldest first.</summary>
    public IEnumerable<T> Events<T>()
        where T : RobotEvent => Robot.Events.History().OfType<T>();

    /// <summary>The host says nothing for longer than the modules' bus watchdog's second stage: every watchdog trips, motors off (the host has not looked yet).</summary>
    public void SilenceBeyondTheWatchdog() => Sim.Advance(TimeSpan.FromMilliseconds(Lb.Definition.Modules.WatchdogOffMs + 10)); // past the second stage: torque off, latched

    /// <summary>
    /// Stalls arm <paramref name="arm"/>'s elbow against an obstacle far beyond what its drive can push, with a setpoint
    /// <paramref name="byRad"/> beyond mid-range: it runs into its current limit.
    /// </summary>
    public void StallElbow(int arm, double byRad)
    {
        Sim.Axis(arm, "elbow").ObstacleTorqueNm = 5;
        var setpoint = Robot.Definition.Joints.Select(j => j.MidRad).ToArray();
        setpoint[3] += byRad;
        Robot.WriteJointSetpoints(arm, setpoint);
    }

    /// <summary>Runs <paramref name="count"/> bus cycles on this thread.</summary>
    public void Cycles(int count)
    {
        for (var i = 0; i < count; i++)
        {
            Robot.RunCycle();
        }
    }

    public void Dispose() => Lb.Dispose();

    private sealed class CountingCheck(Action check) : ICycleCheck
    {
        public void BeforeWrite()
        {
        }

        public void Check() => check();
    }
}
