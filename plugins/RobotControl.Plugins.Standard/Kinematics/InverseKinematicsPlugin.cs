using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Geometry;
using RobotControl.Kinematics.Inverse;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;

namespace RobotControl.Plugins.Standard.Kinematics;

/// <summary>
/// Inverse kinematics of the graph's robot arm (the right-arm model; the left arm's input is mirrored by homing):
/// target position (mm) and orientation (rad) in, one joint angle per joint out (radians, within limits, never NaN),
/// warm-started from the previous solution. When the target is out of reach the joints go to the best reachable pose
/// and <c>fx, fy, fz</c> carry the workspace force k_s (Ph - Pd) in the arm's base frame (zero when reached).
/// <para>
/// With <c>follow</c> and every <c>&lt;joint&gt;.measured</c> input wired (the robot's <c>teleop_enabled</c> and its
/// joint positions, both delayed), teleoperation starts where the arm is: while the robot does not follow, the joints
/// out are the measured ones (the next solve starts from them); on the tick the robot follows, the target is
/// re-anchored so that where it is now maps to the arm's measured tool pose, and from then on the arm moves by the
/// target's motion. So the first pedal-down after start-up, and every re-engagement, moves nothing by itself.
/// </para>
/// </summary>
[PluginType("inverse_kinematics", Description = "CCD + bounded Levenberg-Marquardt IK of the robot arm with workspace-force outputs.")]
public sealed class InverseKinematicsPlugin : Plugin<InverseKinematicsSettings>
{
    private readonly IkSolver _solver;
    private readonly OrientationAxes _axes;
    private readonly InputPort _x;
    private readonly InputPort _y;
    private readonly InputPort _z;
    private readonly InputPort _roll;
    private readonly InputPort _pitch;
    private readonly InputPort _yaw;
    private readonly OutputPort[] _joints;
    private readonly OutputPort _fx;
    private readonly OutputPort _fy;
    private readonly OutputPort _fz;
    private readonly OutputPort _reached;
    private readonly OutputPort _error;
    private readonly InputPort _follow;
    private readonly InputPort[] _measured;
    private readonly double[] _seed;
    private readonly double[] _solution;
    private readonly ChainState _measuredPose;
    private Vector3d _anchorOffset; // added to the target position while following (arm base frame, mm)
    private Rotation3d _anchorRotation = Rotation3d.Identity; // applied before the target rotation while following
    private bool _startsFromMeasured; // follow and the measured joints are wired (known from Start on)
    private bool _following; // the robot followed at the previous tick; false before the first, so the first tick anchors

    /// <summary>Creates the plug-in for the graph's robot.</summary>
    /// <exception cref="InvalidOperationException">The graph names no robot.</exception>
    /// <exception cref="ArgumentException">The initial joints do not match the robot.</exception>
    public InverseKinematicsPlugin(InverseKinematicsSettings settings, PluginContext context)
        : base(settings, context)
    {
        var robot = Context.RequireRobot();
        var chain = new KinematicChain(robot);
        _solver = new IkSolver(chain, new IkOptions
        {
            PositionToleranceMm = Settings.PositionToleranceMm,
            MaxIterations = Settings.MaxIterations,
            MaxRestarts = Settings.MaxRestarts,
            WorkspaceStiffnessNPerMm = Settings.WorkspaceStiffnessNPerMm,
        });
        _axes = Settings.Orientation switch
        {
            OrientationMode.ToolAxis => OrientationAxes.Z,
            OrientationMode.Full => OrientationAxes.All,
            _ => OrientationAxes.None,
        };
        _seed = new double[chain.JointCount];
        _solution = new double[chain.JointCount];
        var initial = Settings.ParseInitialJointsDeg();
        if (initial is null)
        {
            chain.MidRange(_seed);
        }
        else if (initial.Length != chain.JointCount)
        {
            throw new ArgumentException($"initial_joints_deg has {initial.Length} values; {robot.Name} has {chain.JointCount} joints", nameof(settings));
        }
        else
        {
            for (var j = 0; j < _seed.Length; j++)
            {
                _seed[j] = initial[j] * Math.PI / 180.0;
            }

            chain.Clamp(_seed);
        }

        // Outputs start at the start pose, and the position inputs at its tool position, so nothing jumps at start.
        var state = chain.CreateState();
        state.Update(_seed);
        var home = state.ToolPosition;
        _x = DeclareInput("x", "mm", "target x (arm base frame)", home.X);
        _y = DeclareInput("y", "mm", "target y", home.Y);
        _z = DeclareInput("z", "mm", "target z", home.Z);
        _roll = DeclareInput("roll", "rad", "target roll");
        _pitch = DeclareInput("pitch", "rad", "target pitch");
        _yaw = DeclareInput("yaw", "rad", "target yaw");
        _joints = [.. robot.Joints.Select((j, i) => DeclareOutput(j.Name, SafeValue.HoldLastFinite, "rad", $"{j.Name} ({j.Symbol}) angle", _seed[i]))];
        _fx = DeclareOutput("fx", SafeValue.Zero, "N", "workspace force x (arm base frame)");
        _fy = DeclareOutput("fy", SafeValue.Zero, "N", "workspace force y");
        _fz = DeclareOutput("fz", SafeValue.Zero, "N", "workspace force z");
        _reached = DeclareOutput("reached", SafeValue.Zero, "", "1 when the target was reached within tolerance");
        _error = DeclareOutput("error_mm", SafeValue.Zero, "mm", "distance from the target to the reached point");
        _follow = DeclareInput("follow", "", "1 while the robot follows (wire robot.teleop_enabled, delayed, with the measured joints); unwired: 1, the target is used as it is", 1);
        _measured = [.. robot.Joints.Select((j, i) => DeclareInput($"{j.Name}.measured", "rad", $"{j.Name} angle the robot reports (wire the arm's {j.Name}.position from the robot, delayed); with follow, teleoperation starts from it", _seed[i]))];
        _measuredPose = chain.CreateState();
    }

    /// <inheritdoc />
    public override void Start(in TickContext context) => _startsFromMeasured = IsWired(_follow) && _measured.All(IsWired);

    /// <summary>The chain solved for.</summary>
    public KinematicChain Chain => _solver.Chain;

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var position = new Vector3d(Read(_x), Read(_y), Read(_z));
        var rotation = Rotation3d.FromRollPitchYaw(Read(_roll), Read(_pitch), Read(_yaw));
        if (_startsFromMeasured)
        {
            var following = Read(_follow) >= 0.5;
            if (!following)
            {
                FollowMeasured();
                _following = false;
                return;
            }

            if (!_following)
            {
                Anchor(position, rotation);
                _following = true;
            }

            position += _anchorOffset;
            rotation = _anchorRotation * rotation;
        }

        var target = new IkTarget(position, rotation, _axes);
        var result = _solver.Solve(target, _seed, _solution);
        if (result.Status == IkStatus.InvalidTarget)
        {
            // Keep the joints where they are (the solver returned the seed) and push nothing.
            Write(_fx, 0);
            Write(_fy, 0);
            Write(_fz, 0);
            Write(_reached, 0);
            return;
        }

        for (var j = 0; j < _solution.Length; j++)
        {
            Write(_joints[j], _solution[j]);
            _seed[j] = _solution[j];
        }

        Write(_fx, result.WorkspaceForce.X);
        Write(_fy, result.WorkspaceForce.Y);
        Write(_fz, result.WorkspaceForce.Z);
        Write(_reached, result.Reached ? 1 : 0);
        Write(_error, result.PositionErrorMm);
    }

    /// <summary>The robot does not follow: the joints out are the measured ones, and so is the next solve's start.</summary>
    private void FollowMeasured()
    {
        TakeMeasured();
        for (var j = 0; j < _seed.Length; j++)
        {
            Write(_joints[j], _seed[j]);
        }

        Write(_fx, 0);
        Write(_fy, 0);
        Write(_fz, 0);
        Write(_reached, 0);
        Write(_error, 0);
    }

    /// <summary>The robot follows from now: the target as it is now maps to the arm's measured tool pose.</summary>
    private void Anchor(Vector3d position, Rotation3d rotation)
    {
        TakeMeasured();
        _measuredPose.Update(_seed);
        _anchorOffset = _measuredPose.ToolPosition - position;
        _anchorRotation = _measuredPose.ToolRotation * rotation.Transposed();
    }

    /// <summary>The next solve starts from the measured joints (within limits; a non-finite one keeps its last value).</summary>
    private void TakeMeasured()
    {
        for (var j = 0; j < _measured.Length; j++)
        {
            var q = Read(_measured[j]);
            if (double.IsFinite(q))
            {
                _seed[j] = q;
            }
        }

        _solver.Chain.Clamp(_seed);
    }
}
