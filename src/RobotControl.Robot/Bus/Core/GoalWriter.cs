using System.Buffers.Binary;
using RobotControl.Bus.Client;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The cycle's <b>write</b> step: the latest setpoints become motor goals (couplings, manual commands, joint limits;
/// the measured positions while torque is off), under the hold and the step cap, sent to every module in one sync
/// write. Written by the bus thread alone. Other threads ask, lock-free, for what the next write takes up first: a
/// hold (<see cref="HoldAtMeasured"/>), the motors off (<see cref="RequestTorqueOff"/>), faults cleared
/// (<see cref="RequestClear"/>), the modules' bus holds acknowledged (<see cref="RequestHoldAcknowledgement"/>); a
/// supervisor's action therefore reaches the wire at the next write, never from inside the check.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class GoalWriter
{
    private const double StepCapToleranceRad = 1e-9;
    private readonly RobotLayout _layout;
    private readonly BusClient _client;
    private readonly ModuleRoster _roster;
    private readonly SetpointExchange _setpoints;
    private readonly GoalSeed _seed;
    private readonly RobotLifecycle _life;
    private readonly TimeProvider _time;
    private readonly BusInterruption _stop;
    private readonly double[] _goals;
    private readonly double[] _sent;
    private readonly double[] _loop; // per motor: the goal the setpoints (the control loop's) ask, before manual commands, torque and hold
    private readonly double[] _held;
    private readonly double[] _q;
    private readonly double[] _a;
    private readonly double[] _jaw = new double[1];
    private long _lastWrite;
    private bool _capPrimed;
    private int _seedSeen; // the seed generation the step cap last restarted at
    private volatile int _hold; // 0: none, 1: asked at the measured positions, 3: asked at the goals sent (captured at the next write), 2: holding
    private volatile string? _torqueOffRequest;
    private volatile bool _clearRequested;
    private volatile bool _holdAcknowledgementRequested;
    private long _stepCapHits;
    private double _largestCappedStep;

    public GoalWriter(RobotLayout layout, BusClient client, ModuleRoster roster, SetpointExchange setpoints, GoalSeed seed, RobotLifecycle life, BusInterruption stop)
    {
        _stop = stop;
        _layout = layout;
        _client = client;
        _roster = roster;
        _setpoints = setpoints;
        _seed = seed;
        _life = life;
        _time = client.Time;
        _goals = new double[layout.Motors.Length];
        _sent = [.. layout.Motors.Select(m => m.PositionRad)];
        _loop = [.. layout.Motors.Select(m => m.PositionRad)];
        _held = new double[layout.Motors.Length];
        _q = new double[layout.JointCount];
        _a = new double[layout.JointCount];
    }

    /// <summary>Runs before the goals are made, on the bus thread: a requested torque-off, then a requested clear, then a requested hold acknowledgement.</summary>
    public Action<string>? TorqueOff { get; set; }

    /// <summary>Clears the faults in the modules (the module supervisor's), on the bus thread.</summary>
    public Action? Clear { get; set; }

    /// <summary>Acknowledges one module's bus hold, true when done (the module supervisor's), on the bus thread.</summary>
    public Func<RobotController, bool>? AcknowledgeHold { get; set; }

    public long StepCapHits => Interlocked.Read(ref _stepCapHits);

    public double LargestCappedStepRad => Volatile.Read(ref _largestCappedStep);

    public bool IsHolding => _hold != 0;

    /// <summary>True once a write has made goals (<see cref="SentGoal"/> means something).</summary>
    public bool HasWritten => Volatile.Read(ref _capPrimed);

    /// <summary>Freezes every goal at its measured position from the next write on (any thread).</summary>
    public void HoldAtMeasured() => Interlocked.CompareExchange(ref _hold, 1, 0);

    /// <summary>
    /// Freezes every goal at the goal last sent from the next write on (any thread): where the modules were going, so
    /// that setpoints from before a soft trip take the arms up again without a step.
    /// </summary>
    public void HoldAtSent() => Interlocked.CompareExchange(ref _hold, 3, 0);

    /// <summary>The setpoints drive the goals again, each still under the step cap (any thread).</summary>
    public void ReleaseHold() => _hold = 0;

    /// <summary>The motors go off at the next write (any thread); <paramref name="reason"/> is the state change's.</summary>
    public void RequestTorqueOff(string reason) => _torqueOffRequest = reason;

    /// <summary>Faults are cleared at the next write (any thread).</summary>
    public void RequestClear() => _clearRequested = true;

    /// <summary>The modules' bus holds are acknowledged at the next write, before its goals (any thread).</summary>
    public void RequestHoldAcknowledgement() => _holdAcknowledgementRequested = true;

    /// <summary>The modules' bus holds are acknowledged now, between cycles (on the bus thread: set-up that turns the motors on).</summary>
    public void AcknowledgeHoldsNow()
    {
        _holdAcknowledgementRequested = false;
        AcknowledgeHolds();
    }

    /// <summary>
    /// An emergency stop's action (any thread, lock-free): hold, and with <paramref name="torqueOff"/> the motors off, at
    /// the next write; until that write, the work between cycles is cut short and none starts (<see cref="BetweenCycles"/>).
    /// </summary>
    public void EmergencyHold(string reason, bool torqueOff)
    {
        HoldAtMeasured();
        if (torqueOff)
        {
            RequestTorqueOff(reason);
        }

        _stop.Raise(reason);
    }

    /// <summary>The goal last sent to motor <paramref name="index"/>, output radians.</summary>
    public double SentGoal(int index) => Volatile.Read(ref _sent[index]);

    /// <summary>
    /// The goal the setpoints ask of motor <paramref name="index"/> (couplings and joint limits applied), output radians:
    /// what the motor follows when not in manual, and what releasing a manual motor hands it back to.
    /// </summary>
    public double LoopGoal(int index) => Volatile.Read(ref _loop[index]);

    /// <summary>Cycle step <b>write</b>.</summary>
    public void Write()
    {
        var now = _time.GetTimestamp();
        var dt = _lastWrite == 0 ? 0 : (now - _lastWrite) / (double)_time.TimestampFrequency;
        _lastWrite = now;
        _stop.Clear(); // a stop raised from here on is taken by this write or the next; its requests were made before it was raised
        if (_torqueOffRequest is { } reason)
        {
            _torqueOffRequest = null;
            TorqueOff?.Invoke(reason);
        }

        if (_clearRequested)
        {
            _clearRequested = false;
            Clear?.Invoke();
        }

        if (_holdAcknowledgementRequested)
        {
            _holdAcknowledgementRequested = false;
            AcknowledgeHolds();
        }

        ComputeGoals(dt);
        CapAndHold(dt);
        var active = _roster.Active;
        if (!active.Any)
        {
            return;
        }

        var data = active.WriteData;
        for (var i = 0; i < active.Controllers.Length; i++)
        {
            foreach (var m in active.Controllers[i].MotorArray)
            {
                BinaryPrimitives.WriteInt32LittleEndian(data.AsSpan((i * _layout.GoalLength) + (m.Config.Channel * _layout.GoalStride)), m.Config.ToCounts(_goals[m.Index]));
            }
        }

        _client.SyncWrite(_layout.GoalAddress, _layout.GoalLength, active.Ids, data);
    }

    /// <summary>
    /// Every holding module's acknowledgement. The step cap of an acknowledged module's motors restarts from where they
    /// held (their measured positions), not from the goals sent meanwhile, which the module refused: the next goals
    /// move from the held positions at most the cap, never a step toward what was sent during the hold.
    /// </summary>
    private void AcknowledgeHolds()
    {
        foreach (var c in _roster.Active.Controllers)
        {
            if (AcknowledgeHold?.Invoke(c) != true)
            {
                continue;
            }

            foreach (var m in c.MotorArray)
            {
                RestartCap(m);
            }
        }
    }

    /// <summary>The motor's step cap starts again from its measured position, not from the goal sent last.</summary>
    private void RestartCap(RobotMotor m) => Volatile.Write(ref _sent[m.Index], m.PositionRad);

    private void ComputeGoals(double dt)
    {
        for (var arm = 0; arm < _layout.ArmCount; arm++)
        {
            _seed.Joints(_setpoints, arm, _q);
            _layout.Map.JointsToActuators(_q, _a);
            var motors = _layout.MotorOf[arm];
            var kinematic = _layout.KinematicActuator;
            for (var k = 0; k < kinematic.Length; k++)
            {
                if (motors[kinematic[k]] is { } m)
                {
                    _goals[m.Index] = _a[k];
                }
            }

            if (_layout.ToolMotor(arm) is { } tool)
            {
                _goals[tool.Index] = _seed.Jaw(_setpoints, arm, _jaw);
            }
        }

        var torque = _life.TorqueEnabled;
        foreach (var m in _layout.Motors)
        {
            // Joint limits again at the motor (the firmware clamps a third time); the setpoints' goal so clamped is the loop goal.
            var loop = Math.Clamp(_goals[m.Index], m.Config.OutputMinRad, m.Config.OutputMaxRad);
            Volatile.Write(ref _loop[m.Index], loop);
            var goal = m.IsManual ? m.ManualGoal(dt) : torque ? loop : m.PositionRad; // torque off: keep the modules' goals on their positions
            _goals[m.Index] = Math.Clamp(goal, m.Config.OutputMinRad, m.Config.OutputMaxRad);
        }
    }

    /// <summary>The hold and the step cap (no goal moves further in one write than the motor's speed limit times the time since the last).</summary>
    private void CapAndHold(double dt)
    {
        if (_seed.Generation != _seedSeen)
        {
            // The motors went on (from where they are, e.g. just re-homed): the cap starts there, not from the goals
            // sent before, which a re-homing may have left far off (a ramp from there would move the wrong way).
            _seedSeen = _seed.Generation;
            foreach (var m in _layout.Motors)
            {
                RestartCap(m);
            }
        }

        var asked = _hold;
        if (asked is 1 or 3)
        {
            foreach (var m in _layout.Motors)
            {
                _held[m.Index] = Math.Clamp(asked == 3 && _capPrimed ? _sent[m.Index] : m.PositionRad, m.Config.OutputMinRad, m.Config.OutputMaxRad);
            }

            Interlocked.CompareExchange(ref _hold, 2, asked);
        }

        var holding = _hold == 2;
        var torque = _life.TorqueEnabled;
        foreach (var m in _layout.Motors)
        {
            var i = m.Index;
            var goal = holding && torque ? _held[i] : _goals[i];
            if (_capPrimed && torque && dt > 0)
            {
                var cap = BusRobot.StepCapRad(m, dt);
                var step = goal - _sent[i];
                if (Math.Abs(step) > cap + StepCapToleranceRad)
                {
                    goal = _sent[i] + Math.CopySign(cap, step);
                    Interlocked.Increment(ref _stepCapHits);
                    if (Math.Abs(step) > _largestCappedStep)
                    {
                        Volatile.Write(ref _largestCappedStep, Math.Abs(step));
                    }
                }
            }

            _goals[i] = goal;
            Volatile.Write(ref _sent[i], goal);
        }

        Volatile.Write(ref _capPrimed, true);
    }
}
