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
    private readonly double[] _seed;
    private readonly double[] _solution;

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
    }

    /// <summary>The chain solved for.</summary>
    public KinematicChain Chain => _solver.Chain;

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var target = new IkTarget(
            new Vector3d(Read(_x), Read(_y), Read(_z)),
            Rotation3d.FromRollPitchYaw(Read(_roll), Read(_pitch), Read(_yaw)),
            _axes);
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
}
