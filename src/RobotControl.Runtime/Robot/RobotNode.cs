using RobotControl.Definitions.Model;
using RobotControl.Plugins.Sdk;
using RobotControl.Plugins.Sdk.Ports;
using RobotControl.Robot.Control;

namespace RobotControl.Runtime.Robot;

/// <summary>
/// The robot as a graph instance (named <see cref="InstanceName"/>): inputs are joint setpoints per arm
/// (<c>right.elbow</c>, radians, in the arm's own right-arm model) and the jaw (<c>right.jaw</c>); outputs are the
/// joint positions the modules report (<c>right.elbow.position</c>), motor currents (<c>right.elbow.current</c>, A)
/// the robot's fault flags (<c>faults</c>) and <c>teleop_enabled</c> (1 while the run level lets teleoperation drive
/// the arms: the haptic handles' <c>force_enable</c>). The input <c>right.input_age_ms</c> takes how old the input
/// device data driving the arm is (a Touch's <c>sample_age_ms</c>) and hands it to the port (the master timeout);
/// <c>right.input_speed_mm_s</c> takes the hand's speed at that device (a Touch's <c>speed_mm_s</c>): a speed the
/// operator's port calls implausible (a jump) publishes no setpoints for the arm that tick, and the arm holds;
/// <c>pedal</c> and <c>estop</c> (0/1, a foot-pedal plug-in's outputs) are handed to the port when wired: the safety
/// supervisor's run level follows them. Talks to an <see cref="IRobotPort"/> without blocking or allocating.
/// <para>
/// Safety: when anything upstream has faulted the robot holds position (once, then stays held); a non-finite
/// setpoint is never written (the arm holds and <see cref="RejectedSetpoints"/> counts it). Arms without a wired
/// setpoint are not commanded; unwired joints of a commanded arm keep the position read at start.
/// </para>
/// </summary>
public sealed class RobotNode : Plugin
{
    /// <summary>The instance name the robot has in every graph.</summary>
    public const string InstanceName = "robot";

    private readonly RobotDefinition _robot;
    private readonly InputPort[][] _setpoints;
    private readonly InputPort[] _jaws;
    private readonly InputPort[] _inputAges;
    private readonly InputPort[] _inputSpeeds;
    private readonly bool[] _implausible;
    private readonly InputPort _pedal;
    private readonly InputPort _estop;
    private readonly OutputPort[][] _positions;
    private readonly OutputPort[][] _currents;
    private readonly OutputPort _faults;
    private readonly OutputPort _teleopEnabled;
    private readonly double[] _joints;
    private readonly double[] _currentValues;
    private readonly double[][] _commanded;
    private readonly bool[] _commandedThisTick;
    private readonly bool[] _armDriven; // which arms and jaws have wired setpoints, and whether the pedals are wired: from the graph, at Start
    private readonly bool[] _jawDriven;
    private bool _pedalWired;
    private bool _estopWired;
    private IRobotPort? _port;
    private IOperatorPort? _operator;
    private long _rejected;

    /// <summary>Creates the robot's node from its definition; attach a port with <see cref="Attach"/> before starting.</summary>
    public RobotNode(RobotDefinition robot, TimeProvider time, string baseDirectory)
        : base(new PluginContext(InstanceName, robot, time, baseDirectory))
    {
        ArgumentNullException.ThrowIfNull(robot);
        _robot = robot;
        var arms = robot.Arms.Count;
        var jointCount = robot.JointCount;
        _setpoints = new InputPort[arms][];
        _jaws = new InputPort[arms];
        _inputAges = new InputPort[arms];
        _inputSpeeds = new InputPort[arms];
        _implausible = new bool[arms];
        _positions = new OutputPort[arms][];
        _currents = new OutputPort[arms][];
        _commanded = new double[arms][];
        for (var a = 0; a < arms; a++)
        {
            var arm = robot.Arms[a].Name;
            _setpoints[a] = [.. robot.Joints.Select(j => DeclareInput($"{arm}.{j.Name}", "rad", $"{arm} arm {j.Name} setpoint"))];
            _jaws[a] = DeclareInput($"{arm}.jaw", "rad", $"{arm} arm jaw opening setpoint");
            _inputAges[a] = DeclareInput($"{arm}.input_age_ms", "ms", $"how old the input device data driving the {arm} arm is (a Touch's sample_age_ms; unwired: 0, no master timeout)");
            _inputSpeeds[a] = DeclareInput($"{arm}.input_speed_mm_s", "mm/s", $"speed of the hand at the input device driving the {arm} arm, before scaling (a Touch's speed_mm_s; unwired: 0, no jump check)");
            _commanded[a] = new double[jointCount];
        }

        for (var a = 0; a < arms; a++)
        {
            var arm = robot.Arms[a].Name;
            _positions[a] = [.. robot.Joints.Select(j => DeclareOutput($"{arm}.{j.Name}.position", SafeValue.HoldLastFinite, "rad", $"{arm} arm {j.Name} position reported by the modules"))];
            _currents[a] = [.. robot.Actuators.Select(m => DeclareOutput($"{arm}.{m.Name}.current", SafeValue.Zero, "A", $"{arm} arm {m.Label} filtered motor current"))];
        }

        _pedal = DeclareInput("pedal", "", "teleoperation pedal (1 = pressed: PEDAL_DOWN, 0: PEDAL_UP), e.g. a foot_pedals output; unwired: the host presses it");
        _estop = DeclareInput("estop", "", "emergency-stop pedal or button (1 = pressed: E_STOP)");
        _faults = DeclareOutput("faults", SafeValue.HoldLastFinite, "", "robot fault flags (RobotFaults)");
        _teleopEnabled = DeclareOutput("teleop_enabled", SafeValue.Zero, "", "1 while the run level lets teleoperation drive the arms, else 0 (wire it to the haptic handles' force_enable)");
        _joints = new double[jointCount];
        _currentValues = new double[robot.Actuators.Count];
        _commandedThisTick = new bool[arms];
        _armDriven = new bool[arms];
        _jawDriven = new bool[arms];
    }

    /// <summary>The robot.</summary>
    public RobotDefinition Robot => _robot;

    /// <summary>The attached port.</summary>
    public IRobotPort? Port => _port;

    /// <summary>The last tick's <c>teleop_enabled</c>: teleoperation drove the arms (the run level allowed it, nothing upstream faulted).</summary>
    public bool TeleopEnabled { get; private set; } = true;

    /// <summary>True once the robot was told to hold because something upstream faulted.</summary>
    public bool Holding { get; private set; }

    /// <summary>Setpoint vectors refused because they held a non-finite value.</summary>
    public long RejectedSetpoints => Volatile.Read(ref _rejected);

    /// <summary>
    /// Attaches the robot's port and, when a safety supervisor watches the robot, the operator's port (before the graph
    /// starts): pedals and input ages go to <paramref name="operatorPort"/>; without one, teleoperation is always allowed.
    /// </summary>
    public void Attach(IRobotPort port, IOperatorPort? operatorPort = null)
    {
        ArgumentNullException.ThrowIfNull(port);
        if (port.ArmCount != _robot.Arms.Count)
        {
            throw new ArgumentException($"the port drives {port.ArmCount} arms; {_robot.Name} has {_robot.Arms.Count}", nameof(port));
        }

        _port = port;
        _operator = operatorPort;
    }

    /// <summary>The joint setpoints written for <paramref name="arm"/> on the last tick (valid when <see cref="CommandedThisTick"/>).</summary>
    public ReadOnlySpan<double> LastCommanded(int arm) => _commanded[arm];

    /// <summary>True when <paramref name="arm"/> was sent setpoints on the last tick.</summary>
    public bool CommandedThisTick(int arm) => _commandedThisTick[arm];

    /// <inheritdoc />
    public override void Start(in TickContext context)
    {
        var port = _port ?? throw new InvalidOperationException("the robot node has no port attached");
        for (var a = 0; a < _setpoints.Length; a++)
        {
            port.ReadJointPositions(a, _joints);
            for (var j = 0; j < _joints.Length; j++)
            {
                SetInput(_setpoints[a][j].Index, _joints[j]);
            }
        }

        for (var a = 0; a < _setpoints.Length; a++)
        {
            _armDriven[a] = _setpoints[a].Any(IsWired);
            _jawDriven[a] = IsWired(_jaws[a]);
        }

        _pedalWired = IsWired(_pedal);
        _estopWired = IsWired(_estop);
        PublishFeedback(port); // what the first tick's delayed wires carry (e.g. into an IK that starts where the arm is)
        Write(_faults, (int)port.Faults);
        TeleopEnabled = _operator?.TeleopAllowed ?? true;
        Write(_teleopEnabled, TeleopEnabled ? 1 : 0);
    }

    /// <inheritdoc />
    public override void Tick(in TickContext context)
    {
        var port = _port!;
        PublishFeedback(port);
        if (_operator is { } op)
        {
            op.ReportTick();
            for (var a = 0; a < _inputAges.Length; a++)
            {
                op.ReportInputAge(a, Read(_inputAges[a]));
                _implausible[a] = !op.ReportInputSpeed(a, Read(_inputSpeeds[a]));
            }

            if (_pedalWired)
            {
                op.ReportPedal(Read(_pedal) >= 0.5);
            }

            if (_estopWired)
            {
                op.ReportEmergencyStop(Read(_estop) >= 0.5);
            }
        }

        Write(_faults, (int)port.Faults);
        TeleopEnabled = (_operator?.TeleopAllowed ?? true) && !UpstreamFaulted;
        Write(_teleopEnabled, TeleopEnabled ? 1 : 0);
        if (UpstreamFaulted)
        {
            if (!Holding)
            {
                Holding = true;
                port.HoldPosition();
            }

            Array.Clear(_commandedThisTick);
            return;
        }

        for (var a = 0; a < _setpoints.Length; a++)
        {
            _commandedThisTick[a] = false;
            if (!_armDriven[a] || _implausible[a])
            {
                continue; // implausible: a jump at the master, and the operator's side has asked the robot to hold
            }

            var setpoint = _commanded[a];
            var finite = true;
            for (var j = 0; j < setpoint.Length; j++)
            {
                var v = Read(_setpoints[a][j]);
                finite &= double.IsFinite(v);
                setpoint[j] = v;
            }

            if (!finite)
            {
                Interlocked.Increment(ref _rejected);
                continue; // the port keeps the last finite setpoint of this arm
            }

            port.WriteJointSetpoints(a, setpoint);
            _commandedThisTick[a] = true;
            var jaw = Read(_jaws[a]);
            if (_jawDriven[a] && double.IsFinite(jaw))
            {
                port.WriteJawSetpoint(a, jaw);
            }
        }
    }

    /// <summary>The joint positions and motor currents the modules report, on the outputs.</summary>
    private void PublishFeedback(IRobotPort port)
    {
        for (var a = 0; a < _positions.Length; a++)
        {
            port.ReadJointPositions(a, _joints);
            for (var j = 0; j < _joints.Length; j++)
            {
                Write(_positions[a][j], _joints[j]);
            }

            port.ReadMotorCurrents(a, _currentValues);
            for (var m = 0; m < _currentValues.Length; m++)
            {
                Write(_currents[a][m], _currentValues[m]);
            }
        }
    }
}
