using RobotControl.Hardware.Model;
using RobotControl.Robot.Bus;
using RobotControl.Simulation;
using RobotControl.Simulation.Time;
using RobotControl.TestSupport;

namespace RobotControl.Robot.Tests.Bus.Core;

/// <summary>A virtual LB-1.0 and the robot layer on it with a <see cref="TapLink"/> between them.</summary>
internal sealed class TappedLb : IDisposable
{
    private TapLink? _tap;

    public TappedLb(bool start = true, BusRobotOptions? options = null, VirtualRobotOptions? sim = null, RobotDefinition? hostView = null, Action<TapLink>? beforeStart = null)
    {
        Lb = new VirtualLb(sim, hostView, start: false, options, link: inner => _tap = new TapLink(inner));
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

    /// <summary>Runs <paramref name="count"/> bus cycles on this thread.</summary>
    public void Cycles(int count)
    {
        for (var i = 0; i < count; i++)
        {
            Robot.RunCycle();
        }
    }

    public void Dispose() => Lb.Dispose();
}
