using RobotControl.Kinematics.Forward;
using RobotControl.Plugins.Sdk;
using RobotControl.Robot.Control;
using RobotControl.Runtime.Loop;
using RobotControl.Runtime.Robot;

namespace RobotControl.Host.Harness;

/// <summary>
/// Tracking error on the loop thread, after every tick: the distance between the commanded tool position (forward
/// kinematics of the joint setpoints the robot node sent) and the tool position computed from the joint positions the
/// modules report, per commanded arm, on the ticks where teleoperation drives the arms (the robot node's
/// <c>teleop_enabled</c>: at PEDAL_DOWN; a hold after a trip is not tracking). Keeps the RMS and the maximum;
/// allocation-free.
/// </summary>
internal sealed class TrackingMeter : ITickObserver
{
    private readonly RobotNode _node;
    private readonly IRobotPort _port;
    private readonly ChainState _commanded;
    private readonly ChainState _reported;
    private readonly double[] _joints;
    private double _sumSquares;
    private long _samples;
    private double _max;

    public TrackingMeter(RobotNode node, IRobotPort port)
    {
        _node = node;
        _port = port;
        var chain = new KinematicChain(node.Robot);
        _commanded = chain.CreateState();
        _reported = chain.CreateState();
        _joints = new double[chain.JointCount];
    }

    public ITickObserver? Next { get; init; }

    public long Samples => _samples;

    public double RmsMm => _samples == 0 ? 0 : Math.Sqrt(_sumSquares / _samples);

    public double MaxMm => _max;

    /// <summary>The last error of each arm, mm (for progress displays).</summary>
    public double[] LastErrorMm { get; } = new double[8];

    public void AfterTick(in TickContext context)
    {
        for (var arm = 0; arm < _port.ArmCount; arm++)
        {
            if (!_node.TeleopEnabled || !_node.CommandedThisTick(arm))
            {
                continue;
            }

            _commanded.Update(_node.LastCommanded(arm));
            _port.ReadJointPositions(arm, _joints);
            _reported.Update(_joints);
            var error = (_commanded.ToolPosition - _reported.ToolPosition).Length;
            _sumSquares += error * error;
            _samples++;
            _max = Math.Max(_max, error);
            if (arm < LastErrorMm.Length)
            {
                LastErrorMm[arm] = error;
            }
        }

        Next?.AfterTick(context);
    }
}
