using System.Collections.Concurrent;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Hardware.Exchange;
using RobotControl.Hardware.Model;
using RobotControl.Kinematics.Coupling;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// A robot on its module bus: the controllers (modules) of the robot file, found by ID; their motors named after the
/// joints; parameters kept in the modules' FRAM; the joint &lt;-&gt; motor mapping with the couplings; joint limits
/// enforced; and the <see cref="IRobotPort"/> the control loop uses. Split by job over its files: this one (state,
/// construction), <c>BusRobot.Setup.cs</c> (discover, parameters, torque), <c>BusRobot.Homing.cs</c>,
/// <c>BusRobot.Cycle.cs</c> (the bus cycle's steps <see cref="Read"/>, <see cref="Update"/> and <see cref="Write"/>),
/// <c>BusRobot.Supervision.cs</c> (status poll, resets, watchdog) and <c>BusRobot.Port.cs</c>.
/// <para>
/// Its life is a <see cref="RobotStateMachine"/> (<see cref="State"/>), declared in <see cref="DeclareStates"/>:
/// <see cref="RobotState.Disabled"/> -> <see cref="RobotState.Discovered"/> (<see cref="Discover"/>) ->
/// <see cref="RobotState.Homing"/> -> <see cref="RobotState.Homed"/> (<see cref="Home"/>) ->
/// <see cref="RobotState.Enabled"/> (<see cref="EnableTorque"/>), and <see cref="RobotState.Fault"/> when a module
/// stops its motors. Setup calls are refused in states they do not fit, and must not overlap cycles.
/// </para>
/// </summary>
public sealed partial class BusRobot : IRobotPort, IBusCycle, IDisposable
{
    private readonly BusClient _client;
    private readonly ControlTable _table;
    private readonly BusRobotOptions _options;
    private readonly TimeProvider _time;
    private readonly JointMotorMap _map;
    private readonly RobotController[] _controllers;
    private readonly RobotMotor[] _motors;
    private readonly RobotMotor?[][] _motorOf; // [arm][actuator index in the robot file]
    private readonly int[] _kinematicActuator; // kinematic index -> robot-file actuator index
    private readonly int _toolActuator;
    private readonly SeqLock<double>[] _jointSetpoints;
    private readonly SeqLock<double>[] _jawSetpoints;
    private readonly SeqLock<double>[] _jointPositions;
    private readonly SeqLock<double>[] _currents;
    private readonly RobotStateMachine _state;
    private readonly double[][] _lastJointSetpoint; // writer side (control loop)
    private readonly int[] _setpointVersionAtEnable;
    private readonly double[] _goals; // per motor, axis output radians
    private readonly double[] _q;
    private readonly double[] _a;
    private readonly double[] _armCurrents;
    private readonly double[] _jaw = new double[1];
    private readonly ushort _goalAddress;
    private readonly ushort _feedbackAddress;
    private readonly int _goalStride;
    private readonly int _feedbackStride;
    private readonly int _goalLength;
    private readonly ushort _statusAddress;
    private readonly ushort _potAddress;
    private readonly int _potStride;
    private readonly int _potLength;
    private readonly ushort _resetCauseAddress;
    private readonly ushort _watchdogAddress;
    private readonly ushort _torqueAddress;
    private readonly int _watchdogMs;
    private readonly IReadOnlyDictionary<int, string> _resetCauses;
    private byte[] _ids = [];
    private RobotController[] _active = [];
    private byte[] _writeData = [];
    private FeedbackGroup[] _groups = [];
    private byte[] _stateIds = [];
    private int[] _stateLengths = [];
    private byte[] _stateData = [];
    private Reply[] _stateReplies = [];
    private bool _fastReads;
    private byte[] _statusData = [];
    private Reply[] _statusReplies = [];
    private long _cycles;
    private long _lastCycleTimestamp;
    private int _latchedFaults;
    private int _liveFaults;
    private bool _torqueEnabled;
    private bool _homed;
    private volatile bool _clearRequested;
    private volatile bool _stopping;
    private Thread? _thread;

    /// <summary>Opens <paramref name="robot"/> on the bus <paramref name="client"/> talks to (the robot owns the client).</summary>
    /// <exception cref="ArgumentException">The robot file has no modules section.</exception>
    public BusRobot(RobotDefinition robot, BusClient client, BusRobotOptions? options = null)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(client);
        if (robot.Modules.Modules.Count == 0)
        {
            throw new ArgumentException($"{robot.SourceFile}: the robot file has no modules section; nothing to drive on the bus", nameof(robot));
        }

        Definition = robot;
        _inputAgeMs = new double[robot.Arms.Count];
        _client = client;
        _time = client.Time;
        _options = options ?? new BusRobotOptions();
        _table = ControlTable.Firmware;
        _map = new JointMotorMap(robot);
        _kinematicActuator = _map.Actuators.Select(a => IndexOf(robot, a)).ToArray();
        _toolActuator = _map.ToolActuator is { } tool ? IndexOf(robot, tool) : -1;
        _watchdogMs = robot.Modules.WatchdogMs;

        var controllers = new List<RobotController>();
        var motors = new List<RobotMotor>();
        _motorOf = new RobotMotor?[robot.Arms.Count][];
        for (var arm = 0; arm < robot.Arms.Count; arm++)
        {
            _motorOf[arm] = new RobotMotor?[robot.Actuators.Count];
        }

        foreach (var module in robot.Modules.Modules)
        {
            var controller = new RobotController(module, controllers.Count);
            var own = new List<RobotMotor>();
            foreach (var m in module.Motors.OrderBy(m => m.Channel))
            {
                var motor = new RobotMotor(new MotorConfig(robot, module, m), controller, motors.Count);
                motors.Add(motor);
                own.Add(motor);
                _motorOf[module.Arm][m.ActuatorIndex] = motor;
            }

            controller.MotorArray = own.ToArray();
            controllers.Add(controller);
        }

        _controllers = controllers.ToArray();
        _motors = motors.ToArray();
        var arms = robot.Arms.Count;
        _jointSetpoints = Enumerable.Range(0, arms).Select(_ => new SeqLock<double>(robot.JointCount)).ToArray();
        _jawSetpoints = Enumerable.Range(0, arms).Select(_ => new SeqLock<double>(1)).ToArray();
        _jointPositions = Enumerable.Range(0, arms).Select(_ => new SeqLock<double>(robot.JointCount)).ToArray();
        _currents = Enumerable.Range(0, arms).Select(_ => new SeqLock<double>(robot.Actuators.Count)).ToArray();
        _lastJointSetpoint = Enumerable.Range(0, arms).Select(_ => new double[robot.JointCount]).ToArray();
        _setpointVersionAtEnable = new int[arms * 2];
        _goals = new double[_motors.Length];
        _q = new double[robot.JointCount];
        _a = new double[robot.JointCount];
        _armCurrents = new double[robot.Actuators.Count];

        var goal = _table["goal_position"];
        var position = _table["present_position"];
        var maxChannels = _controllers.Max(c => c.ChannelSpan);
        _goalAddress = goal.At(0);
        _goalStride = goal.Stride;
        _goalLength = ((maxChannels - 1) * goal.Stride) + goal.Size;
        _feedbackAddress = position.At(0);
        _feedbackStride = position.Stride;
        _statusAddress = _table["hardware_error_status"].At(0);
        var pot = _table["pot_raw"];
        _potAddress = pot.At(0);
        _potStride = pot.Stride;
        _potLength = ((maxChannels - 1) * pot.Stride) + pot.Size;
        _resetCauseAddress = _table["reset_cause"].At(0);
        _watchdogAddress = _table["bus_watchdog"].At(0);
        _torqueAddress = _table["torque_enable"].At(0);
        _resetCauses = _table.Codes("reset_cause");
        if (_resetCauseAddress != _statusAddress + 1 || _watchdogAddress != _statusAddress + 2 || _table["bus_watchdog"].Size != StatusPollLength - 2)
        {
            throw new InvalidOperationException("the control table no longer keeps reset_cause and bus_watchdog (2 bytes) right after hardware_error_status; update the status poll");
        }

        _state = new RobotStateMachine(_time);
        DeclareStates();
    }

    /// <inheritdoc />
    public RobotDefinition Definition { get; }

    /// <inheritdoc />
    public int ArmCount => Definition.Arms.Count;

    /// <summary>The protocol client.</summary>
    public BusClient Client => _client;

    /// <summary>Every configured controller, in file order.</summary>
    public IReadOnlyList<RobotController> Controllers => _controllers;

    /// <summary>Every configured motor.</summary>
    public IReadOnlyList<RobotMotor> Motors => _motors;

    /// <summary>The joint &lt;-&gt; motor mapping.</summary>
    public JointMotorMap Map => _map;

    /// <summary>Completed bus cycles.</summary>
    public long Cycles => Interlocked.Read(ref _cycles);

    /// <summary>Things that happened (discovery problems, module reset, missing, back, watchdog, bus errors), oldest first.</summary>
    public ConcurrentQueue<RobotEvent> Events { get; } = new();

    /// <summary>The robot's state now.</summary>
    public RobotState State => _state.Current;

    /// <summary>Every state change so far with its time and reason, oldest first.</summary>
    public IReadOnlyList<RobotTransition> StateHistory => _state.History;

    /// <inheritdoc />
    public RobotFaults Faults => (RobotFaults)(Volatile.Read(ref _latchedFaults) | Volatile.Read(ref _liveFaults));

    /// <summary>The motor named <c>arm.joint</c>, e.g. <c>right.elbow</c>.</summary>
    /// <exception cref="KeyNotFoundException">No such motor.</exception>
    public RobotMotor Motor(string fullName) =>
        _motors.FirstOrDefault(m => m.Config.FullName == fullName)
        ?? throw new KeyNotFoundException($"no motor '{fullName}' (motors: {string.Join(", ", _motors.Select(m => m.Config.FullName))})");

    /// <summary>The controller with bus ID <paramref name="id"/>, or null.</summary>
    public RobotController? Controller(byte id) => _controllers.FirstOrDefault(c => c.Id == id);

    /// <summary>
    /// The robot's states, each declared once: what entering it does and which states may follow. Torque is on in
    /// <see cref="RobotState.Enabled"/> and stays as it was in <see cref="RobotState.Fault"/> (the modules stopped
    /// their motors; clearing the faults re-arms them).
    /// </summary>
    private void DeclareStates()
    {
        _state.Declare(RobotState.Disabled, null, RobotState.Discovered);
        _state.Declare(RobotState.Discovered, () => (_torqueEnabled, _homed) = (false, false), RobotState.Homing, RobotState.Enabled, RobotState.Fault);
        _state.Declare(RobotState.Homing, () => _torqueEnabled = false, RobotState.Homed, RobotState.Discovered);
        _state.Declare(RobotState.Homed, () => (_torqueEnabled, _homed) = (false, true), RobotState.Discovered, RobotState.Homing, RobotState.Enabled, RobotState.Fault);
        _state.Declare(RobotState.Enabled, () => _torqueEnabled = true, RobotState.Discovered, RobotState.Homed, RobotState.Fault);
        _state.Declare(RobotState.Fault, null, RobotState.Enabled, RobotState.Discovered, RobotState.Homed);
    }

    /// <summary>The state motors-off leads to: homed if the robot was homed since it was last discovered.</summary>
    private RobotState MotorsOffState => _homed ? RobotState.Homed : RobotState.Discovered;

    private void SetLatched(RobotFaults fault) => Interlocked.Or(ref _latchedFaults, (int)fault);

    private void SetLive(RobotFaults fault, bool on)
    {
        if (on)
        {
            Interlocked.Or(ref _liveFaults, (int)fault);
        }
        else
        {
            Interlocked.And(ref _liveFaults, ~(int)fault);
        }
    }

    private static int IndexOf(RobotDefinition robot, ActuatorDefinition actuator)
    {
        for (var i = 0; i < robot.Actuators.Count; i++)
        {
            if (ReferenceEquals(robot.Actuators[i], actuator))
            {
                return i;
            }
        }

        return -1;
    }

    private sealed record FeedbackGroup(RobotController[] Controllers, byte[] Ids, int Length, ArraySegment<byte> Data, ArraySegment<Reply> Replies);
}