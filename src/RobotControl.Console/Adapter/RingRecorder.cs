using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Bus;
using RobotControl.Plugins.Sdk.Observation;
using RobotControl.Runtime.Graph;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The loop's tick observer that feeds the console: after every tick it copies every output signal of the graph, plus
/// the joint setpoints the robot node wrote (<c>robot.right.elbow.command</c>) and, per motor, the goal it follows
/// (<c>robot.right.elbow.desired</c>: the loop's setpoint, or its jog or setpoint target while in manual, as last sent)
/// and its measured axis output (<c>robot.right.elbow.measured</c>), into the <see cref="SignalRing"/>.
/// Allocation-free per tick; the motors' values are the robot core's, read lock-free.
/// </summary>
internal sealed class RingRecorder : ITickObserver
{
    private readonly SignalView _outputs;
    private readonly RobotNode _node;
    private readonly double[] _row;
    private readonly int _jointCount;
    private readonly BusRobot _robot;
    private readonly RobotMotor[] _motors;

    /// <summary>Creates the recorder and its ring for <paramref name="program"/>, the robot <paramref name="node"/> and the motors of <paramref name="robot"/>.</summary>
    public RingRecorder(GraphProgram program, RobotNode node, BusRobot robot, int capacity)
    {
        _robot = robot;
        _motors = [.. robot.Motors];
        _outputs = program.OutputSignals;
        _node = node;
        _jointCount = node.Robot.JointCount;
        var names = new List<string>(_outputs.Names);
        var units = _outputs.Names.Select(n => UnitOf(program, n)).ToList();
        foreach (var arm in node.Robot.Arms)
        {
            foreach (var joint in node.Robot.Joints)
            {
                names.Add(CommandSignal(arm.Name, joint.Name));
                units.Add("rad");
            }
        }

        foreach (var m in _motors)
        {
            names.Add(DesiredSignal(m.Config.FullName));
            units.Add("rad");
            names.Add(MeasuredSignal(m.Config.FullName));
            units.Add("rad");
        }

        _row = new double[names.Count];
        Ring = new SignalRing(names, units, capacity);
        InitialiseCommands();
    }

    /// <summary>The ring the recorder writes.</summary>
    public SignalRing Ring { get; }

    /// <summary>The ring signal of an arm joint's commanded value.</summary>
    public static string CommandSignal(string arm, string joint) => $"{RobotNode.InstanceName}.{arm}.{joint}.command";

    /// <summary>The ring signal of an arm joint's measured value.</summary>
    public static string PositionSignal(string arm, string joint) => $"{RobotNode.InstanceName}.{arm}.{joint}.position";

    /// <summary>The ring signal of the goal a motor (<c>arm.motor</c>) follows, output radians: the goal last sent to it.</summary>
    public static string DesiredSignal(string motor) => $"{RobotNode.InstanceName}.{motor}.desired";

    /// <summary>The ring signal of a motor's (<c>arm.motor</c>) measured axis output, radians.</summary>
    public static string MeasuredSignal(string motor) => $"{RobotNode.InstanceName}.{motor}.measured";

    /// <inheritdoc />
    public void AfterTick(in TickContext context)
    {
        _outputs.Values.CopyTo(_row);
        var at = _outputs.Names.Count;
        for (var a = 0; a < _node.Robot.Arms.Count; a++, at += _jointCount)
        {
            if (_node.CommandedThisTick(a))
            {
                _node.LastCommanded(a).CopyTo(_row.AsSpan(at, _jointCount));
            }
        }

        foreach (var m in _motors)
        {
            _row[at++] = _robot.SentGoalRad(m);
            _row[at++] = m.PositionRad;
        }

        Ring.Append(context.Elapsed.TotalSeconds, _row);
    }

    private void InitialiseCommands()
    {
        // Until an arm is commanded its ghost shows the joint mid-range.
        var at = _outputs.Names.Count;
        for (var a = 0; a < _node.Robot.Arms.Count; a++)
        {
            foreach (var joint in _node.Robot.Joints)
            {
                _row[at++] = joint.MidRad;
            }
        }
    }

    private static string UnitOf(GraphProgram program, string signal)
    {
        var dot = signal.IndexOf('.', StringComparison.Ordinal);
        var instance = program.Order.FirstOrDefault(p => p.Name == signal[..dot]);
        return instance?.Outputs.FirstOrDefault(o => o.Name == signal[(dot + 1)..])?.Units ?? string.Empty;
    }
}
