using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Coupling;
using RobotControl.Modules;

namespace RobotControl.Robot.Calibration;

/// <summary>
/// Where one module's motors go while their pots are calibrated, as axis output angles (radians, one per motor of the
/// module in channel order): the fixture pose (<see cref="Reference"/>: every joint at the middle of its range, the
/// jaw half open) and, for each motor, a sweep from there to the low end of its range, to the high end and back. A
/// coupled motor's ends are corners of the joint-limit box (e.g. a differential shoulder's yaw and pitch both at their
/// minimum), reached along straight lines in joint space, so every joint stays within its limits all the way (less
/// <see cref="MarginRad"/>); the module's other motors move with it as the coupling says.
/// </summary>
public sealed class PotSweepPlan
{
    /// <summary>How far inside each joint limit a sweep turns back, radians (half a degree).</summary>
    public const double MarginRad = 0.5 * Math.PI / 180;

    private readonly RobotDefinition _robot;
    private readonly JointMotorMap _map;
    private readonly int[] _actuator;

    /// <summary>The plan of <paramref name="module"/> of <paramref name="robot"/>.</summary>
    public PotSweepPlan(RobotDefinition robot, ModuleDefinition module)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(module);
        _robot = robot;
        _map = new JointMotorMap(robot);
        Module = module;
        Motors = [.. module.Motors.OrderBy(m => m.Channel).Select(m => new MotorConfig(robot, module, m))];
        _actuator = [.. Motors.Select(m => _map.IndexOfActuator(m.Actuator.Name))];
        Reference = Outputs(Mid(), JawMid());
    }

    /// <summary>The robot file.</summary>
    public RobotDefinition Robot => _robot;

    /// <summary>The module.</summary>
    public ModuleDefinition Module { get; }

    /// <summary>Its motors, in channel order (the order of every angle array here).</summary>
    public IReadOnlyList<MotorConfig> Motors { get; }

    /// <summary>The fixture pose: every joint at the middle of its range (the robot file's limits), the jaw half open.</summary>
    public IReadOnlyList<double> Reference { get; }

    /// <summary>The way points of motor <paramref name="index"/>'s sweep: the fixture pose, its low end, its high end, the fixture pose.</summary>
    public IReadOnlyList<double[]> Sweep(int index)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(index);
        ArgumentOutOfRangeException.ThrowIfGreaterThanOrEqual(index, Motors.Count);
        var k = _actuator[index];
        double[] low, high;
        if (k < 0)
        {
            // The jaw drive: its own range, the arm's joints at the fixture pose.
            low = Outputs(Mid(), _robot.Tool.JawMinRad + MarginRad);
            high = Outputs(Mid(), _robot.Tool.JawMaxRad - MarginRad);
        }
        else
        {
            low = Outputs(Corner(k, lowEnd: true), JawMid());
            high = Outputs(Corner(k, lowEnd: false), JawMid());
        }

        return [[.. Reference], low, high, [.. Reference]];
    }

    private double[] Mid() => [.. _robot.Joints.Select(j => j.MidRad)];

    private double JawMid() => 0.5 * (_robot.Tool.JawMinRad + _robot.Tool.JawMaxRad);

    /// <summary>The joints at the corner of the limit box where actuator <paramref name="k"/> is at its low (or high) end; joints it does not use at mid-range.</summary>
    private double[] Corner(int k, bool lowEnd)
    {
        var q = Mid();
        for (var j = 0; j < q.Length; j++)
        {
            var c = _map.Coefficient(k, j);
            if (c != 0)
            {
                var joint = _robot.Joints[j];
                q[j] = (c > 0) == lowEnd ? joint.MinRad + MarginRad : joint.MaxRad - MarginRad;
            }
        }

        return q;
    }

    /// <summary>The module's motors' output angles with the arm's joints at <paramref name="joints"/> and the jaw at <paramref name="jaw"/>.</summary>
    private double[] Outputs(double[] joints, double jaw)
    {
        var actuators = new double[_map.JointCount];
        _map.JointsToActuators(joints, actuators);
        return [.. _actuator.Select(k => k < 0 ? jaw : actuators[k])];
    }
}
