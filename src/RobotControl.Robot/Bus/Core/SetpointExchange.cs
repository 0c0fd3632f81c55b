using RobotControl.Definitions.Exchange;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The joint and jaw setpoints, from the control loop to the bus: written by the loop thread alone
/// (<see cref="WriteJoints"/>, <see cref="WriteJaw"/>, <see cref="HoldAtFeedback"/>), read by the bus thread's goal
/// writer. Values are limited to the joint ranges; a non-finite value is never published: that joint keeps its last
/// setpoint and the rejection is counted (the robot's <c>SetpointRejected</c> fault until faults are cleared). When the
/// motors go on, the goal writer seeds the goals from the measured positions (<see cref="GoalWriter"/>); the loop side
/// sees the seed's generation change and takes the measured positions as its last setpoints, so no second thread ever
/// writes here.
/// </summary>
[WrittenBy(RobotThread.Loop)]
internal sealed class SetpointExchange
{
    private readonly RobotLayout _layout;
    private readonly FeedbackExchange _feedback;
    private readonly GoalSeed _seed;
    private readonly SeqLock<double>[] _joints;
    private readonly SeqLock<double>[] _jaws;
    private readonly double[][] _last; // per arm: the last published joint setpoints
    private int _seedSeen;
    private long _rejected;

    public SetpointExchange(RobotLayout layout, FeedbackExchange feedback, GoalSeed seed)
    {
        _layout = layout;
        _feedback = feedback;
        _seed = seed;
        _joints = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new SeqLock<double>(layout.JointCount))];
        _jaws = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new SeqLock<double>(1))];
        _last = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new double[layout.JointCount])];
    }

    /// <summary>Setpoints refused so far (non-finite values, bad arms or lengths); any thread reads it.</summary>
    public long Rejected => Interlocked.Read(ref _rejected);

    public void WriteJoints(int arm, ReadOnlySpan<double> jointsRad)
    {
        var n = _layout.JointCount;
        if ((uint)arm >= (uint)_layout.ArmCount || jointsRad.Length < n)
        {
            Interlocked.Increment(ref _rejected);
            return;
        }

        TakeSeed();
        Span<double> q = stackalloc double[n];
        var last = _last[arm];
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

            var joint = _layout.Definition.Joints[j];
            q[j] = Math.Clamp(v, joint.MinRad, joint.MaxRad);
        }

        if (rejected)
        {
            Interlocked.Increment(ref _rejected);
        }

        q.CopyTo(last);
        _joints[arm].Write(q);
    }

    public void WriteJaw(int arm, double jawRad)
    {
        if ((uint)arm >= (uint)_layout.ArmCount || !double.IsFinite(jawRad))
        {
            Interlocked.Increment(ref _rejected);
            return;
        }

        Span<double> jaw = [Math.Clamp(jawRad, _layout.Map.JawMinRad, _layout.Map.JawMaxRad)];
        _jaws[arm].Write(jaw);
    }

    /// <summary>Every arm's setpoints become its measured positions (a plug-in faulted: hold).</summary>
    public void HoldAtFeedback()
    {
        Span<double> q = stackalloc double[_layout.JointCount];
        for (var arm = 0; arm < _layout.ArmCount; arm++)
        {
            _feedback.ReadJoints(arm, q);
            q.CopyTo(_last[arm]);
            _joints[arm].Write(q);
            if (_layout.ToolMotor(arm) is { } tool)
            {
                Span<double> jaw = [tool.PositionRad];
                _jaws[arm].Write(jaw);
            }
        }

        foreach (var m in _layout.Motors)
        {
            if (m.IsManual)
            {
                m.RequestHold();
            }
        }
    }

    /// <summary>Sees every joint setpoint vector the bus thread reads, as it reads it (tests: nothing torn reaches a goal).</summary>
    internal SetpointsRead? Observer { get; set; }

    /// <summary>The bus thread's read of an arm's joint setpoints; returns how many writes they are (0: none yet).</summary>
    public int ReadJoints(int arm, Span<double> q)
    {
        var version = _joints[arm].Read(q);
        Observer?.Invoke(arm, q);
        return version;
    }

    /// <summary>How many joint setpoint writes of <paramref name="arm"/> there were.</summary>
    public int JointVersion(int arm) => _joints[arm].Version;

    /// <summary>How many jaw setpoint writes of <paramref name="arm"/> there were.</summary>
    public int JawVersion(int arm) => _jaws[arm].Version;

    /// <summary>The bus thread's read of an arm's jaw setpoint; returns how many writes it is (0: none yet).</summary>
    public int ReadJaw(int arm, Span<double> jaw) => _jaws[arm].Read(jaw);

    /// <summary>After a seed (motors on), the measured positions are the last setpoints a rejected value falls back to.</summary>
    private void TakeSeed()
    {
        var seed = _seed.Generation;
        if (seed == _seedSeen)
        {
            return;
        }

        _seedSeen = seed;
        for (var arm = 0; arm < _layout.ArmCount; arm++)
        {
            _feedback.ReadJoints(arm, _last[arm]);
        }
    }
}

/// <summary>An arm's joint setpoints as the bus thread read them.</summary>
internal delegate void SetpointsRead(int arm, ReadOnlySpan<double> jointsRad);
