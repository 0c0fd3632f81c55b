using RobotControl.Bus.Protocol;
using RobotControl.Plugins.Sdk.Faults;
using RobotControl.Robot.Bus;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Robot;
using RobotControl.Simulation;

namespace RobotControl.Host.Harness;

/// <summary>
/// Applies the safety faults of <c>--inject</c> (<see cref="TimedFault"/>) to a virtual run at their times, from the
/// tick hook: each one once, when the first tick at or after its time runs. Allocation-free per tick.
/// </summary>
internal sealed class SafetyFaultSchedule
{
    /// <summary>Torque that locks a rotor (far above any motor's stall torque), N·m.</summary>
    private const double LockedRotorTorqueNm = 1e3;

    /// <summary>A current spike: the sensor reads this many times the motor's limit more.</summary>
    private const double CurrentSpikeLimits = 2;

    /// <summary>Where the modules keep their bus watchdog period.</summary>
    private static readonly ushort WatchdogAddress = ControlTable.Firmware["bus_watchdog"].At(0);

    private readonly Pending[] _pending;
    private readonly VirtualRobot _sim;
    private readonly BusRobot _robot;
    private readonly double[] _nan;
    private int _next;

    /// <summary>Resolves <paramref name="faults"/> against the session's robot and graph; times count from <paramref name="begin"/> (bus clock).</summary>
    /// <exception cref="FormatException">A fault names an unknown motor or plug-in (the message lists the known ones).</exception>
    public SafetyFaultSchedule(IReadOnlyList<TimedFault> faults, VirtualRobot sim, BusRobot robot, LoadedGraph graph, long begin, long frequency)
    {
        _sim = sim;
        _robot = robot;
        _nan = new double[robot.Definition.JointCount];
        Array.Fill(_nan, double.NaN);
        _pending = [.. faults.Where(f => f.Kind != TimedFaultKind.Silent).Select(f => Resolve(f, sim, graph, begin + (long)(f.At.TotalSeconds * frequency))).OrderBy(p => p.At)];
    }

    /// <summary>Faults not applied yet.</summary>
    public int Remaining => _pending.Length - _next;

    /// <summary>Applies every fault due by <paramref name="timestamp"/> that acts before the tick (all but NaN; a silent module is scheduled in the virtual robot itself).</summary>
    public void BeforeTick(long timestamp)
    {
        while (_next < _pending.Length && _pending[_next].At <= timestamp && _pending[_next].Fault.Kind != TimedFaultKind.Nan)
        {
            var p = _pending[_next++];
            switch (p.Fault.Kind)
            {
                case TimedFaultKind.Watchdog:
                    _ = _sim.WriteTable(p.Module, WatchdogAddress, [0, 0]); // bus_watchdog 0: off
                    break;
                case TimedFaultKind.Stall:
                    _sim.Advance(p.Fault.Duration); // the bus clock moves on, nobody talks to the modules
                    break;
                case TimedFaultKind.Stuck:
                    p.Axis!.ObstacleTorqueNm = LockedRotorTorqueNm;
                    break;
                case TimedFaultKind.Current:
                    p.Axis!.CurrentSenseOffsetA = CurrentSpikeLimits * p.Axis.Config.Motor.CurrentLimitA;
                    break;
                case TimedFaultKind.Pot:
                    p.Axis!.PotFailedRaw = 0; // an open wiper pulled to ground
                    break;
                case TimedFaultKind.Jump:
                case TimedFaultKind.Stale:
                    p.Device!.Inject(p.DeviceFault!);
                    break;
            }
        }
    }

    /// <summary>Applies a NaN fault due by <paramref name="timestamp"/>: after the graph wrote its setpoints, its arm gets NaN.</summary>
    public void AfterTick(long timestamp)
    {
        while (_next < _pending.Length && _pending[_next].At <= timestamp && _pending[_next].Fault.Kind == TimedFaultKind.Nan)
        {
            _robot.WriteJointSetpoints(_pending[_next++].Arm, _nan);
        }
    }

    private static Pending Resolve(TimedFault f, VirtualRobot sim, LoadedGraph graph, long at)
    {
        switch (f.Kind)
        {
            case TimedFaultKind.Stuck:
            case TimedFaultKind.Current:
            case TimedFaultKind.Pot:
                var axis = sim.Axes.FirstOrDefault(a => string.Equals(a.Config.FullName, f.Target, StringComparison.OrdinalIgnoreCase))
                    ?? throw new FormatException($"--inject '{f}': no motor '{f.Target}' (known: {string.Join(", ", sim.Axes.Select(a => a.Config.FullName))})");
                return new Pending(f, at, axis, -1);
            case TimedFaultKind.Jump:
            case TimedFaultKind.Stale:
                return new Pending(f, at, null, -1, DeviceFaultTargets.Resolve(f, graph.Program.Order), DeviceFaultTargets.FaultOf(f));
            case TimedFaultKind.Watchdog:
                return new Pending(f, at, null, -1, Module: HeadlessRun.ResolveModule(graph.Robot!, f.Target));
            case TimedFaultKind.Nan:
                var prefix = $"{RobotNode.InstanceName}.";
                var wire = graph.Document.Wires.FirstOrDefault(w => w.From.StartsWith(f.Target + ".", StringComparison.Ordinal) && w.To.StartsWith(prefix, StringComparison.Ordinal))
                    ?? throw new FormatException($"--inject '{f}': plug-in '{f.Target}' drives no arm of the robot node (plug-ins wired to it: {string.Join(", ", graph.Document.Wires.Where(w => w.To.StartsWith(prefix, StringComparison.Ordinal)).Select(w => w.From.Split('.')[0]).Distinct())})");
                var armName = wire.To[prefix.Length..].Split('.')[0];
                var arm = graph.Robot!.Arms.Select(a => a.Name).ToList().IndexOf(armName);
                return new Pending(f, at, null, arm);
            default:
                return new Pending(f, at, null, -1);
        }
    }

    private sealed record Pending(TimedFault Fault, long At, VirtualAxis? Axis, int Arm, IFaultInjectable? Device = null, DeviceFault? DeviceFault = null, byte Module = 0);
}
