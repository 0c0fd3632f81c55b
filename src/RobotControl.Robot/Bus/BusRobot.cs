using System.Buffers.Binary;
using System.Collections.Concurrent;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Hardware.Model;
using RobotControl.Kinematics.Coupling;
using RobotControl.Robot.Control;
using RobotControl.Robot.Exchange;
using RobotControl.Robot.Modules;

namespace RobotControl.Robot.Bus;

/// <summary>
/// A robot on its module bus: the controllers (modules) of the robot file, found by ID; their motors named after the
/// joints; parameters kept in the modules' FRAM; the joint &lt;-&gt; motor mapping with the couplings; joint limits
/// enforced; and the <see cref="IRobotPort"/> the control loop uses. Each bus cycle sync-writes every goal position
/// and sync-reads every position and current, allocation-free. Cycles run on this object's own thread
/// (<see cref="Start"/>, for real links) or on the caller's (<see cref="RunFor"/>, <see cref="RunCycle"/>: a virtual
/// bus on a simulated clock). Setup calls (<see cref="Discover"/>, <see cref="CheckParameters"/>,
/// <see cref="WriteParameters"/>, <see cref="Home"/>, <see cref="EnableTorque"/>) must not overlap cycles.
/// </summary>
public sealed class BusRobot : IRobotPort, IDisposable
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
    private readonly SeqLockValues[] _jointSetpoints;
    private readonly SeqLockValues[] _jawSetpoints;
    private readonly SeqLockValues[] _jointPositions;
    private readonly SeqLockValues[] _currents;
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
    private readonly ushort _resetCauseAddress;
    private readonly ushort _watchdogAddress;
    private readonly ushort _torqueAddress;
    private readonly int _watchdogMs;
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
        _jointSetpoints = Enumerable.Range(0, arms).Select(_ => new SeqLockValues(robot.JointCount)).ToArray();
        _jawSetpoints = Enumerable.Range(0, arms).Select(_ => new SeqLockValues(1)).ToArray();
        _jointPositions = Enumerable.Range(0, arms).Select(_ => new SeqLockValues(robot.JointCount)).ToArray();
        _currents = Enumerable.Range(0, arms).Select(_ => new SeqLockValues(robot.Actuators.Count)).ToArray();
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
        _resetCauseAddress = _table["reset_cause"].At(0);
        _watchdogAddress = _table["bus_watchdog"].At(0);
        _torqueAddress = _table["torque_enable"].At(0);
        if (_resetCauseAddress != _statusAddress + 1)
        {
            throw new InvalidOperationException("the control table no longer keeps reset_cause right after hardware_error_status; update the status poll");
        }
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

    /// <summary>Things that happened (module reset, missing, watchdog, rejected setpoints), oldest first.</summary>
    public ConcurrentQueue<string> Events { get; } = new();

    /// <inheritdoc />
    public RobotFaults Faults => (RobotFaults)(Volatile.Read(ref _latchedFaults) | Volatile.Read(ref _liveFaults));

    /// <summary>The motor named <c>arm.joint</c>, e.g. <c>right.elbow</c>.</summary>
    /// <exception cref="KeyNotFoundException">No such motor.</exception>
    public RobotMotor Motor(string fullName) =>
        _motors.FirstOrDefault(m => m.Config.FullName == fullName)
        ?? throw new KeyNotFoundException($"no motor '{fullName}' (motors: {string.Join(", ", _motors.Select(m => m.Config.FullName))})");

    /// <summary>The controller with bus ID <paramref name="id"/>, or null.</summary>
    public RobotController? Controller(byte id) => _controllers.FirstOrDefault(c => c.Id == id);

    // ---------------------------------------------------------------- setup

    /// <summary>
    /// Broadcast-pings the bus and compares what answers with the robot file: missing, unknown and mismatched
    /// modules are listed; present ones take part in the cycles.
    /// </summary>
    public DiscoveryReport Discover()
    {
        var found = new PingInfo[253];
        var n = _client.Discover(found);
        var answered = found.AsSpan(0, n).ToArray();
        var present = new List<RobotController>();
        var missing = new List<RobotController>();
        var mismatched = new List<string>();
        var model = (ushort)_table["model_number"].Default;
        var motorCount = _table["motor_count"].At(0);
        Span<byte> one = stackalloc byte[1];
        foreach (var c in _controllers)
        {
            var hit = Array.FindIndex(answered, p => p.Id == c.Id);
            if (hit < 0)
            {
                // A ping of its own gets past one corrupted broadcast reply.
                if (_client.Ping(c.Id, out var info).Outcome == ReplyOutcome.Ok)
                {
                    answered = [.. answered, info];
                    hit = answered.Length - 1;
                }
            }

            if (hit < 0)
            {
                Volatile.Write(ref c.PresentFlag, false);
                missing.Add(c);
                continue;
            }

            c.ModelNumber = answered[hit].ModelNumber;
            c.FirmwareVersion = answered[hit].FirmwareVersion;
            var ok = true;
            if (c.ModelNumber != model)
            {
                mismatched.Add($"id {c.Id} \"{c.Name}\": model number {c.ModelNumber}, expected {model} (not a RobotControl motor module)");
                ok = false;
            }
            else if (_client.Read(c.Id, motorCount, one).Succeeded && one[0] < c.ChannelSpan)
            {
                mismatched.Add($"id {c.Id} \"{c.Name}\": drives {one[0]} motors, the robot file uses channels up to {c.ChannelSpan - 1}");
                ok = false;
            }

            Volatile.Write(ref c.PresentFlag, ok);
            c.ConsecutiveMisses = 0;
            (ok ? present : missing).Add(c);
        }

        var unknown = answered.Where(p => _controllers.All(c => c.Id != p.Id)).ToArray();
        RebuildActive();
        AcknowledgeStartup();
        var report = new DiscoveryReport(present, missing.Where(m => !mismatched.Any(s => s.StartsWith($"id {m.Id} ", StringComparison.Ordinal))).ToArray(), unknown, mismatched);
        foreach (var line in report.Lines().Where(l => !l.StartsWith("found", StringComparison.Ordinal)))
        {
            Events.Enqueue(line);
        }

        SetLive(RobotFaults.ModuleMissing, report.Missing.Count > 0 || mismatched.Count > 0);
        return report;
    }

    /// <summary>Reads every present module's persistent area and lists the values that differ from the robot file.</summary>
    public IReadOnlyList<ParameterMismatch> CheckParameters()
    {
        var result = new List<ParameterMismatch>();
        var (start, end) = _table.PersistentArea;
        var block = new byte[end - start];
        foreach (var c in _active)
        {
            var reply = _client.ReadMapped(c.Id, _table, start, block);
            if (!reply.Succeeded)
            {
                throw new IOException($"module {c.Id} \"{c.Name}\": reading its parameters failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)})");
            }

            foreach (var p in ModuleParameters.For(Definition, c.Definition, _table))
            {
                var actual = p.Field.Decode(block.AsSpan(p.Address - start, p.Field.Size));
                if (actual != p.Value)
                {
                    result.Add(new ParameterMismatch(c.Id, p, actual));
                }
            }
        }

        return result;
    }

    /// <summary>Writes the robot file's parameters into every present module's FRAM (each write is durable when acknowledged).</summary>
    /// <returns>How many values were written.</returns>
    /// <exception cref="IOException">A module refused or did not acknowledge a value.</exception>
    public int WriteParameters()
    {
        var count = 0;
        Span<byte> value = stackalloc byte[4];
        foreach (var c in _active)
        {
            foreach (var p in ModuleParameters.For(Definition, c.Definition, _table))
            {
                p.Field.Encode(p.Value, value);
                var reply = _client.Write(c.Id, p.Address, value[..p.Field.Size]);
                if (!reply.Succeeded)
                {
                    throw new IOException($"module {c.Id} \"{c.Name}\": writing {p} failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)})");
                }

                count++;
            }
        }

        return count;
    }

    /// <summary>Writes one persistent parameter of one motor (or module-wide field) and reads it back.</summary>
    /// <exception cref="IOException">The module refused the value or read back something else.</exception>
    public long WriteParameter(byte moduleId, string field, int motor, long value)
    {
        var f = _table[field];
        Span<byte> bytes = stackalloc byte[4];
        f.Encode(value, bytes);
        var reply = _client.Write(moduleId, f.At(motor), bytes[..f.Size]);
        if (!reply.Succeeded)
        {
            var locked = f.Persistent && StatusErrors.Number(reply.Error) == StatusError.Access ? ": the persistent area is locked while torque is on, turn torque off first" : string.Empty;
            throw new IOException($"module {moduleId}: writing {field}[{motor}] = {value} failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}){locked}");
        }

        var back = ReadParameter(moduleId, field, motor);
        return back == value ? back : throw new IOException($"module {moduleId}: {field}[{motor}] reads back {back} after writing {value}");
    }

    /// <summary>Reads one control-table value.</summary>
    /// <exception cref="IOException">The module does not answer.</exception>
    public long ReadParameter(byte moduleId, string field, int motor = 0)
    {
        var f = _table[field];
        Span<byte> bytes = stackalloc byte[4];
        var reply = _client.Read(moduleId, f.At(motor), bytes[..f.Size]);
        return reply.Outcome == ReplyOutcome.Ok
            ? f.Decode(bytes)
            : throw new IOException($"module {moduleId}: reading {field}[{motor}] failed ({reply.Outcome})");
    }

    /// <summary>
    /// Homes every motor of the present modules from its joint pot and verifies the result, motor by motor. Each module
    /// gets one <c>home_request</c> for its calibrated motors: the firmware sets their position, goal and setpoint to
    /// the pot position (through its calibration table), clears their pot-mismatch and position-lost bits and saves
    /// the position record. Then each motor's position is read back and compared with its pot through the same
    /// calibration (within the module's <c>pot_mismatch_tolerance</c>), and its <c>motor_error</c> bits are checked.
    /// Motors without a pot calibration keep their position (<see cref="HomingOutcome.NotCalibrated"/>). A module that
    /// refuses or does not answer is reported for each of its motors; the others are still homed.
    /// </summary>
    /// <exception cref="InvalidOperationException">
    /// Torque is on. The firmware refuses to re-home a driven motor: its new coordinates would turn the next goal into
    /// a sudden move. Turn torque off first and on again afterwards (which makes every setpoint the homed position).
    /// </exception>
    public IReadOnlyList<HomingResult> Home()
    {
        if (_torqueEnabled)
        {
            throw new InvalidOperationException("homing needs the motors off: a driven motor must not change coordinates under the control loop; call EnableTorque(false) first");
        }

        var results = new List<HomingResult>();
        foreach (var c in _active)
        {
            HomeModule(c, results);
        }

        PublishPositionsFromMotors();
        return results;
    }

    private void HomeModule(RobotController c, List<HomingResult> results)
    {
        var (start, end) = _table.PersistentArea;
        var block = new byte[end - start];
        if (!_client.ReadMapped(c.Id, _table, start, block).Succeeded)
        {
            foreach (var m in c.Motors)
            {
                results.Add(new HomingResult(m, HomingOutcome.NoReply, -1, double.NaN, double.NaN, HardwareErrors.None, "reading the module's pot calibration failed"));
            }

            return;
        }

        var mask = 0;
        foreach (var m in c.Motors)
        {
            if (PersistentValue(block, start, "pot_cal_count", m.Config.Channel) >= 2)
            {
                mask |= 1 << m.Config.Channel;
            }
        }

        var request = mask == 0 ? new Reply(ReplyOutcome.Ok, 0) : _client.Write(c.Id, _table["home_request"].At(0), [(byte)mask]);
        var tolerance = PersistentValue(block, start, "pot_mismatch_tolerance", 0);
        var errors = new byte[c.ChannelSpan];
        var errorsRead = _client.Read(c.Id, _table["motor_error"].At(0), errors).Succeeded;
        foreach (var m in c.Motors)
        {
            var calibrated = ((mask >> m.Config.Channel) & 1) != 0;
            results.Add(VerifyHoming(m, calibrated, request, block, start, tolerance, errorsRead ? (HardwareErrors)errors[m.Config.Channel] : null));
        }
    }

    private HomingResult VerifyHoming(RobotMotor m, bool calibrated, Reply request, byte[] block, int start, long tolerance, HardwareErrors? errors)
    {
        var ch = m.Config.Channel;
        var hasRaw = TryReadParameter(m.Controller.Id, "pot_raw", ch, out var raw);
        var hasPosition = TryReadParameter(m.Controller.Id, "present_position", ch, out var position);
        var positionRad = hasPosition ? m.Config.ToRadians(position) : double.NaN;
        if (hasPosition)
        {
            m.Publish(positionRad, m.CurrentA);
        }

        var potRaw = hasRaw ? (int)raw : -1;
        var potPosition = hasRaw && calibrated ? PotToPosition(block, start, ch, potRaw) : 0;
        var potRad = hasRaw && calibrated ? m.Config.ToRadians(potPosition) : double.NaN;
        var motorErrors = errors ?? HardwareErrors.None;
        HomingResult Result(HomingOutcome outcome, string detail) => new(m, outcome, potRaw, potRad, positionRad, motorErrors, detail);

        if (!calibrated)
        {
            return Result(HomingOutcome.NotCalibrated, "no pot calibration (pot_cal_count < 2): position kept; write the robot file's parameters (robotctl params) and home again");
        }

        if (request.Outcome != ReplyOutcome.Ok)
        {
            return Result(HomingOutcome.NoReply, $"the home request got no valid reply ({request.Outcome})");
        }

        if (!request.Succeeded)
        {
            return Result(HomingOutcome.Refused, $"the module refused the home request (status error {StatusErrors.Describe(request.Error)}): is torque on in the module, or a pot calibration missing?");
        }

        if (!hasRaw || !hasPosition || errors is null)
        {
            return Result(HomingOutcome.NoReply, "reading the pot, position or errors back failed");
        }

        var left = motorErrors & (HardwareErrors.PotMismatch | HardwareErrors.PositionLost);
        if (left != HardwareErrors.None)
        {
            return Result(HomingOutcome.VerifyFailed, $"error bits still set: {left}");
        }

        var diff = Math.Abs(position - potPosition);
        return diff > tolerance
            ? Result(HomingOutcome.VerifyFailed, $"position {position} differs from the pot's {potPosition} by {diff} counts (tolerance {tolerance})")
            : Result(HomingOutcome.Homed, string.Empty);
    }

    private long PersistentValue(byte[] block, int start, string field, int motor) =>
        _table[field].Decode(block.AsSpan(_table[field].At(motor) - start));

    private bool TryReadParameter(byte moduleId, string field, int motor, out long value)
    {
        var f = _table[field];
        Span<byte> bytes = stackalloc byte[4];
        var ok = _client.Read(moduleId, f.At(motor), bytes[..f.Size]).Succeeded;
        value = ok ? f.Decode(bytes) : 0;
        return ok;
    }

    /// <summary>
    /// Turns the motors on (arming each module's bus watchdog) or off. Turning on first makes every setpoint the
    /// present position, so nothing moves until the control loop or a manual command says so.
    /// </summary>
    /// <exception cref="IOException">A module refuses (e.g. its watchdog error is latched: clear faults first).</exception>
    public void EnableTorque(bool on)
    {
        if (on)
        {
            ReadPresentPositions();
            for (var arm = 0; arm < ArmCount; arm++)
            {
                _jointPositions[arm].Read(_q);
                _jointSetpoints[arm].Write(_q);
                _q.AsSpan().CopyTo(_lastJointSetpoint[arm]);
                _jaw[0] = _toolActuator >= 0 && _motorOf[arm][_toolActuator] is { } tool ? tool.PositionRad : 0;
                _jawSetpoints[arm].Write(_jaw);
            }

            foreach (var m in _motors)
            {
                m.ReleaseManual();
            }
        }

        foreach (var c in _active)
        {
            Arm(c, on);
        }

        _torqueEnabled = on;
    }

    /// <summary>Clears latched faults here and in the modules (hardware errors, watchdog) and re-enables torque if it was on.</summary>
    public void ClearFaults() => _clearRequested = true;

    // ---------------------------------------------------------------- cycles

    /// <summary>Runs bus cycles on a thread of its own until <see cref="Stop"/> (real links).</summary>
    public void Start()
    {
        if (_thread is not null)
        {
            return;
        }

        _stopping = false;
        _thread = new Thread(Loop) { IsBackground = true, Name = $"bus {Definition.Name}", Priority = ThreadPriority.AboveNormal };
        _thread.Start();
    }

    /// <summary>Stops the bus thread.</summary>
    public void Stop()
    {
        _stopping = true;
        _thread?.Join();
        _thread = null;
    }

    /// <summary>
    /// Runs bus cycles on the calling thread until <paramref name="duration"/> has passed on the client's clock (a
    /// virtual bus advances its simulated clock as the cycles wait for bytes). The last cycle may end a little later.
    /// </summary>
    public void RunFor(TimeSpan duration)
    {
        var target = _time.GetTimestamp() + (long)(duration.TotalSeconds * _time.TimestampFrequency);
        Span<byte> idle = stackalloc byte[16];
        while (_time.GetTimestamp() < target)
        {
            if (_ids.Length == 0)
            {
                // Nothing to talk to: let the time pass on the link (a virtual bus simulates meanwhile).
                var left = target - _time.GetTimestamp();
                _client.Link.Read(idle, TimeSpan.FromSeconds(left / (double)_time.TimestampFrequency));
                continue;
            }

            RunCycle();
        }
    }

    /// <summary>One full-state exchange: sync write of every goal, sync read of every position and current.</summary>
    public void RunCycle()
    {
        var now = _time.GetTimestamp();
        var dt = _lastCycleTimestamp == 0 ? 0 : (now - _lastCycleTimestamp) / (double)_time.TimestampFrequency;
        _lastCycleTimestamp = now;
        if (_clearRequested)
        {
            _clearRequested = false;
            ClearInModules();
        }

        ComputeGoals(dt);
        var ids = _ids;
        if (ids.Length > 0)
        {
            for (var i = 0; i < _active.Length; i++)
            {
                foreach (var m in _active[i].MotorArray)
                {
                    BinaryPrimitives.WriteInt32LittleEndian(_writeData.AsSpan((i * _goalLength) + (m.Config.Channel * _goalStride)), m.Config.ToCounts(_goals[m.Index]));
                }
            }

            _client.SyncWrite(_goalAddress, _goalLength, ids, _writeData);

            // One FAST BULK READ of every module's feedback (its own length) when all modules can answer it, else one
            // sync read per feedback length.
            _client.FullStateRead(_feedbackAddress, _stateIds, _stateLengths, _stateData, _stateReplies, _fastReads);

            ProcessFeedback();
        }

        var cycle = Interlocked.Increment(ref _cycles);
        if (ids.Length > 0 && cycle % _options.StatusPollCycles == 0)
        {
            PollStatus();
        }

        if (cycle % _options.ReprobeCycles == 0)
        {
            Reprobe();
        }
    }

    // ---------------------------------------------------------------- IRobotPort

    /// <inheritdoc />
    public void WriteJointSetpoints(int arm, ReadOnlySpan<double> jointsRad)
    {
        var n = Definition.JointCount;
        if ((uint)arm >= (uint)ArmCount || jointsRad.Length < n)
        {
            SetLatched(RobotFaults.SetpointRejected);
            return;
        }

        Span<double> q = stackalloc double[n];
        var last = _lastJointSetpoint[arm];
        var rejected = false;
        for (var j = 0; j < n; j++)
        {
            var v = jointsRad[j];
            if (!double.IsFinite(v))
            {
                rejected = true;
                q[j] = last[j];
                continue;
            }

            var joint = Definition.Joints[j];
            q[j] = Math.Clamp(v, joint.MinRad, joint.MaxRad);
        }

        if (rejected)
        {
            SetLatched(RobotFaults.SetpointRejected);
        }

        q.CopyTo(last);
        _jointSetpoints[arm].Write(q);
    }

    /// <inheritdoc />
    public void WriteJawSetpoint(int arm, double jawRad)
    {
        if ((uint)arm >= (uint)ArmCount || !double.IsFinite(jawRad))
        {
            SetLatched(RobotFaults.SetpointRejected);
            return;
        }

        Span<double> jaw = [Math.Clamp(jawRad, _map.JawMinRad, _map.JawMaxRad)];
        _jawSetpoints[arm].Write(jaw);
    }

    /// <inheritdoc />
    public void ReadJointPositions(int arm, Span<double> jointsRad) => _jointPositions[arm].Read(jointsRad);

    /// <inheritdoc />
    public void ReadMotorCurrents(int arm, Span<double> currentsA) => _currents[arm].Read(currentsA);

    /// <inheritdoc />
    public void HoldPosition()
    {
        Span<double> q = stackalloc double[Definition.JointCount];
        for (var arm = 0; arm < ArmCount; arm++)
        {
            _jointPositions[arm].Read(q);
            q.CopyTo(_lastJointSetpoint[arm]);
            _jointSetpoints[arm].Write(q);
            if (_toolActuator >= 0 && _motorOf[arm][_toolActuator] is { } tool)
            {
                Span<double> jaw = [tool.PositionRad];
                _jawSetpoints[arm].Write(jaw);
            }
        }

        foreach (var m in _motors)
        {
            if (m.IsManual)
            {
                m.SetSetpoint(m.PositionRad);
            }
        }
    }

    /// <inheritdoc />
    public void Dispose()
    {
        Stop();
        _client.Dispose();
    }

    // ---------------------------------------------------------------- internals

    private void Loop()
    {
        var period = (long)(_options.MinimumCyclePeriod.TotalSeconds * _time.TimestampFrequency);
        while (!_stopping)
        {
            var start = _time.GetTimestamp();
            try
            {
                RunCycle();
            }
            catch (IOException ex)
            {
                Events.Enqueue($"bus error: {ex.Message}");
                SetLive(RobotFaults.BusDegraded, true);
                Thread.Sleep(10);
            }

            while (period > 0 && _time.GetTimestamp() - start < period && !_stopping)
            {
                Thread.SpinWait(50);
            }
        }
    }

    private void ComputeGoals(double dt)
    {
        for (var arm = 0; arm < ArmCount; arm++)
        {
            _jointSetpoints[arm].Read(_q);
            _map.JointsToActuators(_q, _a);
            var motors = _motorOf[arm];
            for (var k = 0; k < _kinematicActuator.Length; k++)
            {
                if (motors[_kinematicActuator[k]] is { } m)
                {
                    _goals[m.Index] = _a[k];
                }
            }

            if (_toolActuator >= 0 && motors[_toolActuator] is { } tool)
            {
                _jawSetpoints[arm].Read(_jaw);
                _goals[tool.Index] = _jaw[0];
            }
        }

        foreach (var m in _motors)
        {
            var goal = m.IsManual ? m.ManualGoal(dt) : _goals[m.Index];
            if (!_torqueEnabled && !m.IsManual)
            {
                goal = m.PositionRad; // torque off: keep the modules' goals on their positions
            }

            // Joint limits again at the motor (the firmware clamps a third time).
            _goals[m.Index] = Math.Clamp(goal, m.Config.OutputMinRad, m.Config.OutputMaxRad);
        }
    }

    private void ProcessFeedback()
    {
        var alert = false;
        var lost = false;
        var limited = false;
        foreach (var g in _groups)
        {
            ProcessGroup(g, ref alert, ref lost, ref limited);
        }

        PublishPositionsFromMotors();
        var missing = false;
        foreach (var c in _controllers)
        {
            missing |= !c.Present;
        }

        SetLive(RobotFaults.ModuleMissing, missing);
        SetLive(RobotFaults.BusDegraded, lost);
        SetLive(RobotFaults.CurrentLimited, limited);
        if (alert)
        {
            PollStatus();
        }
    }

    private void ProcessGroup(FeedbackGroup g, ref bool alert, ref bool lost, ref bool limited)
    {
        for (var i = 0; i < g.Controllers.Length; i++)
        {
            var c = g.Controllers[i];
            var reply = g.Replies[i];
            if (reply.Outcome != ReplyOutcome.Ok)
            {
                lost = true;
                if (++c.ConsecutiveMisses == _options.MissingAfterCycles)
                {
                    Volatile.Write(ref c.PresentFlag, false);
                    Events.Enqueue($"module {c.Id} \"{c.Name}\" stopped answering");
                }

                continue;
            }

            if (c.ConsecutiveMisses >= _options.MissingAfterCycles)
            {
                Volatile.Write(ref c.PresentFlag, true);
                Events.Enqueue($"module {c.Id} \"{c.Name}\" answers again");
            }

            c.ConsecutiveMisses = 0;
            alert |= reply.Alert && c.HardwareErrorStatus == 0; // a new alert; known ones are polled on schedule
            var block = g.Data.AsSpan(i * g.Length, g.Length);
            foreach (var m in c.MotorArray)
            {
                var at = block[(m.Config.Channel * _feedbackStride)..];
                var counts = BinaryPrimitives.ReadInt32LittleEndian(at);
                var raw = BinaryPrimitives.ReadUInt16LittleEndian(at[4..]);
                var amps = m.Config.ToAmps(raw);
                m.Publish(m.Config.ToRadians(counts), amps);
                limited |= amps >= _options.CurrentLimitedFraction * m.CurrentLimitA;
            }
        }
    }

    private void PublishPositionsFromMotors()
    {
        for (var arm = 0; arm < ArmCount; arm++)
        {
            var motors = _motorOf[arm];
            for (var k = 0; k < _kinematicActuator.Length; k++)
            {
                _a[k] = motors[_kinematicActuator[k]] is { } m ? m.PositionRad : 0;
            }

            _map.ActuatorsToJoints(_a, _q);
            _jointPositions[arm].Write(_q);
            for (var k = 0; k < _armCurrents.Length; k++)
            {
                _armCurrents[k] = motors[k] is { } m ? m.CurrentA : 0;
            }

            _currents[arm].Write(_armCurrents);
        }
    }

    private void PollStatus()
    {
        if (_ids.Length == 0)
        {
            return;
        }

        _client.SyncRead(_statusAddress, 2, _ids, _statusData, _statusReplies);
        for (var i = 0; i < _active.Length; i++)
        {
            if (_statusReplies[i].Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            var c = _active[i];
            var status = (HardwareErrors)_statusData[2 * i];
            var cause = _statusData[(2 * i) + 1];
            c.HardwareErrorStatus = (byte)status;
            if (cause != 0)
            {
                HandleReset(c, cause, status);
            }

            if ((status & HardwareErrors.BusWatchdog) != 0 && (_latchedFaults & (int)RobotFaults.WatchdogTripped) == 0)
            {
                SetLatched(RobotFaults.WatchdogTripped);
                Events.Enqueue($"module {c.Id} \"{c.Name}\": bus watchdog tripped, motors stopped");
            }

            if ((status & (HardwareErrors.Hall | HardwareErrors.PotMismatch)) != 0 && (_latchedFaults & (int)RobotFaults.HardwareError) == 0)
            {
                SetLatched(RobotFaults.HardwareError);
                Events.Enqueue($"module {c.Id} \"{c.Name}\": hardware error {status}");
            }

            // The firmware latches over-current whenever a current limit engages: that is the limit doing its job
            // (CurrentLimited), not a fault. Acknowledge it when nothing else is latched, so the alert flag clears.
            if ((status & HardwareErrors.OverCurrent) != 0)
            {
                SetLive(RobotFaults.CurrentLimited, true);
                if ((status & ~(HardwareErrors.OverCurrent | HardwareErrors.PositionLost)) == 0)
                {
                    _ = _client.Write(c.Id, _statusAddress, [0]);
                    c.HardwareErrorStatus = 0;
                }
            }
        }
    }

    private void HandleReset(RobotController c, byte cause, HardwareErrors status)
    {
        c.Resets++;
        SetLatched(RobotFaults.ModuleReset);
        var why = cause switch { 1 => "power-on", 2 => "brown-out", 3 => "watchdog", 4 => "software", 5 => "reset pin", 6 => "lockup", _ => $"cause {cause}" };
        var resumed = (status & HardwareErrors.PositionLost) == 0;
        var mismatch = (status & HardwareErrors.PotMismatch) != 0;
        Events.Enqueue($"module {c.Id} \"{c.Name}\" reset ({why}); " +
            (resumed ? "resumed its position from FRAM" : "had no position record and homed from its pot") +
            (mismatch ? "; its position disagrees with the pot: motors left off" : string.Empty));
        _ = _client.Write(c.Id, _resetCauseAddress, [0]);
        if (!mismatch && _torqueEnabled)
        {
            Arm(c, true);
        }
        else if (mismatch)
        {
            SetLatched(RobotFaults.HardwareError);
        }
    }

    private void Arm(RobotController c, bool on)
    {
        Span<byte> watchdog = stackalloc byte[2];
        BinaryPrimitives.WriteUInt16LittleEndian(watchdog, (ushort)(on ? _watchdogMs : 0));
        Span<byte> torque = stackalloc byte[c.ChannelSpan];
        foreach (var m in c.Motors)
        {
            torque[m.Config.Channel] = on ? (byte)1 : (byte)0;
        }

        // Torque first, then the watchdog: a stall between the two writes must not trip a watchdog that refuses the torque.
        var t = _client.Write(c.Id, _torqueAddress, torque);
        var w = _client.Write(c.Id, _watchdogAddress, watchdog);
        if (!w.Succeeded || !t.Succeeded)
        {
            Span<byte> status = stackalloc byte[2];
            var known = _client.Read(c.Id, _statusAddress, status).Succeeded;
            throw new IOException(TorqueRefusal.Describe(c.Id, c.Name, on, t, w, known ? ((HardwareErrors)status[0], status[1]) : null));
        }
    }

    private void ClearInModules()
    {
        foreach (var c in _active)
        {
            _ = _client.Write(c.Id, _statusAddress, [0, 0]);
            c.HardwareErrorStatus = 0;
            if (_torqueEnabled)
            {
                try
                {
                    Arm(c, true);
                }
                catch (IOException ex)
                {
                    Events.Enqueue(ex.Message);
                }
            }
        }

        Volatile.Write(ref _latchedFaults, 0);
    }

    /// <summary>A module's reset cause from before the host connected is history, not a fault: note it and clear it.</summary>
    private void AcknowledgeStartup()
    {
        Span<byte> two = stackalloc byte[2];
        foreach (var c in _active)
        {
            if (!_client.Read(c.Id, _statusAddress, two).Succeeded)
            {
                continue;
            }

            c.HardwareErrorStatus = two[0];
            if (two[1] != 0)
            {
                _ = _client.Write(c.Id, _resetCauseAddress, [0]);
            }
        }
    }

    private void Reprobe()
    {
        foreach (var c in _controllers)
        {
            if (c.Present || _client.Ping(c.Id, out var info).Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            c.ModelNumber = info.ModelNumber;
            c.FirmwareVersion = info.FirmwareVersion;
            c.ConsecutiveMisses = 0;
            Volatile.Write(ref c.PresentFlag, true);
            Events.Enqueue($"module {c.Id} \"{c.Name}\" answers again");
            RebuildActive();
        }
    }

    private void ReadPresentPositions()
    {
        Span<byte> four = stackalloc byte[4];
        foreach (var c in _active)
        {
            foreach (var m in c.Motors)
            {
                if (_client.Read(c.Id, _table["present_position"].At(m.Config.Channel), four).Succeeded)
                {
                    m.Publish(m.Config.ToRadians(BinaryPrimitives.ReadInt32LittleEndian(four)), m.CurrentA);
                }
            }
        }

        PublishPositionsFromMotors();
    }

    private void RebuildActive()
    {
        _active = _controllers.Where(c => c.Present).ToArray();
        _ids = _active.Select(c => c.Id).ToArray();
        _writeData = new byte[_ids.Length * _goalLength];
        // Modules grouped by feedback length; the groups' buffers are consecutive slices of the full-state read's.
        var ordered = _active.GroupBy(c => c.ChannelSpan).OrderByDescending(g => g.Key).SelectMany(g => g).ToArray();
        _stateIds = ordered.Select(c => c.Id).ToArray();
        _stateLengths = ordered.Select(c => c.ChannelSpan * _feedbackStride).ToArray();
        _stateData = new byte[_stateLengths.Sum()];
        _stateReplies = new Reply[ordered.Length];
        _fastReads = ordered.All(c => c.FirmwareVersion >= BusClient.FastReadFirmwareVersion);
        var (module, offset) = (0, 0);
        _groups = ordered.GroupBy(c => c.ChannelSpan).Select(g =>
        {
            var members = g.ToArray();
            var length = g.Key * _feedbackStride;
            var group = new FeedbackGroup(members, members.Select(c => c.Id).ToArray(), length, new ArraySegment<byte>(_stateData, offset, members.Length * length), new ArraySegment<Reply>(_stateReplies, module, members.Length));
            (module, offset) = (module + members.Length, offset + (members.Length * length));
            return group;
        }).ToArray();
        _statusData = new byte[_ids.Length * 2];
        _statusReplies = new Reply[_ids.Length];
    }

    private long PotToPosition(byte[] block, int start, int channel, int raw)
    {
        long Field(string name, int index = 0) => _table[name].Decode(block.AsSpan(_table[name].At(channel) - start + index));
        var n = (int)Field("pot_cal_count");
        if (n < 2)
        {
            return 0;
        }

        var pos0 = Field("pot_cal_pos0");
        var step = Field("pot_cal_step");
        var best = pos0;
        var bestDistance = long.MaxValue;
        for (var i = 0; i + 1 < n; i++)
        {
            var r0 = Field($"pot_cal_raw{i}");
            var r1 = Field($"pot_cal_raw{i + 1}");
            if (((r0 <= raw && raw <= r1) || (r1 <= raw && raw <= r0)) && r0 != r1)
            {
                return pos0 + (i * step) + ((raw - r0) * step / (r1 - r0));
            }

            if (Math.Abs(raw - r0) < bestDistance)
            {
                bestDistance = Math.Abs(raw - r0);
                best = pos0 + (i * step);
            }

            if (Math.Abs(raw - r1) < bestDistance)
            {
                bestDistance = Math.Abs(raw - r1);
                best = pos0 + ((i + 1) * step);
            }
        }

        return best;
    }

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
