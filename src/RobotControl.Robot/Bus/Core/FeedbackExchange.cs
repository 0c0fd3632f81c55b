using System.Buffers.Binary;
using RobotControl.Bus.Client;
using RobotControl.Definitions.Exchange;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The feedback, from the modules to the control loop: the cycle's <b>read</b> step (one full-state read of every
/// present module into the receive buffers) and its <b>publish</b> step (each motor's position and current, the arms'
/// joint positions through the inverse coupling, which modules answer). Written by the bus thread alone; any thread
/// reads the published values (<see cref="ReadJoints"/>, <see cref="ReadCurrents"/>, the motors' outputs).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class FeedbackExchange
{
    private readonly RobotLayout _layout;
    private readonly BusClient _client;
    private readonly ModuleRoster _roster;
    private readonly BusRobotOptions _options;
    private readonly RobotEventStream _events;
    private readonly SeqLock<double>[] _joints;
    private readonly SeqLock<double>[] _currents;
    private readonly double[] _q;
    private readonly double[] _a;
    private readonly double[] _armCurrents;

    public FeedbackExchange(RobotLayout layout, BusClient client, ModuleRoster roster, BusRobotOptions options, RobotEventStream events)
    {
        _layout = layout;
        _client = client;
        _roster = roster;
        _options = options;
        _events = events;
        _joints = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new SeqLock<double>(layout.JointCount))];
        _currents = [.. Enumerable.Range(0, layout.ArmCount).Select(_ => new SeqLock<double>(layout.Definition.Actuators.Count))];
        _q = new double[layout.JointCount];
        _a = new double[layout.JointCount];
        _armCurrents = new double[layout.Definition.Actuators.Count];
    }

    /// <summary>What the last publish found: a module asked for attention, modules missing, replies lost, a motor at its limit.</summary>
    public bool Alert { get; private set; }

    public void ReadJoints(int arm, Span<double> jointsRad) => _joints[arm].Read(jointsRad);

    public void ReadCurrents(int arm, Span<double> currentsA) => _currents[arm].Read(currentsA);

    /// <summary>
    /// Cycle step <b>read</b>: one FAST BULK READ of every module's feedback (its own length) when all modules can
    /// answer it, else one sync read per feedback length. Nothing is published yet.
    /// </summary>
    public void Read()
    {
        var active = _roster.Active;
        if (active.Any)
        {
            _client.FullStateRead(_layout.FeedbackAddress, active.StateIds, active.StateLengths, active.StateData, active.StateReplies, active.FastReads);
        }
    }

    /// <summary>Cycle step <b>publish</b>: what <see cref="Read"/> received becomes the motors' and arms' feedback.</summary>
    public void Publish(RobotFaultFlags faults)
    {
        var active = _roster.Active;
        Alert = false;
        if (!active.Any)
        {
            return;
        }

        var alert = false;
        var lost = false;
        var limited = false;
        foreach (var g in active.Groups)
        {
            PublishGroup(g, ref alert, ref lost, ref limited);
        }

        PublishFromMotors();
        var missing = false;
        foreach (var c in _layout.Controllers)
        {
            missing |= !c.Present;
        }

        faults.SetLive(RobotFaults.ModuleMissing, missing);
        faults.SetLive(RobotFaults.BusDegraded, lost);
        faults.SetLive(RobotFaults.CurrentLimited, limited);
        Alert = alert;
    }

    /// <summary>
    /// A cycle the link failed (the bus thread caught its <see cref="IOException"/>): every present module missed its
    /// reply, as if its feedback had not come, so the supervisor's module-silent check sees the silence.
    /// </summary>
    public void CycleLost(RobotFaultFlags faults)
    {
        foreach (var c in _roster.Active.Controllers)
        {
            Missed(c);
        }

        faults.SetLive(RobotFaults.BusDegraded, true);
    }

    /// <summary>The arms' joint positions and currents from the motors' latest values.</summary>
    public void PublishFromMotors()
    {
        for (var arm = 0; arm < _layout.ArmCount; arm++)
        {
            var motors = _layout.MotorOf[arm];
            var kinematic = _layout.KinematicActuator;
            for (var k = 0; k < kinematic.Length; k++)
            {
                _a[k] = motors[kinematic[k]] is { } m ? m.PositionRad : 0;
            }

            _layout.Map.ActuatorsToJoints(_a, _q);
            _joints[arm].Write(_q);
            for (var k = 0; k < _armCurrents.Length; k++)
            {
                _armCurrents[k] = motors[k] is { } m ? m.CurrentA : 0;
            }

            _currents[arm].Write(_armCurrents);
        }
    }

    /// <summary>Reads every present motor's position one module at a time (set-up, before the motors go on).</summary>
    public void ReadPresentPositions()
    {
        Span<byte> four = stackalloc byte[4];
        foreach (var c in _roster.Active.Controllers)
        {
            foreach (var m in c.MotorArray)
            {
                if (_client.Read(c.Id, _layout.Table["present_position"].At(m.Config.Channel), four).Succeeded)
                {
                    m.Publish(m.Config.ToRadians(BinaryPrimitives.ReadInt32LittleEndian(four)), m.CurrentA);
                }
            }
        }

        PublishFromMotors();
    }

    private void Missed(RobotController c)
    {
        if (++c.ConsecutiveMisses == _options.MissingAfterCycles)
        {
            Volatile.Write(ref c.PresentFlag, false);
            _events.Publish(new ModuleStoppedAnswering(c.Id, c.Name));
        }
    }

    private void PublishGroup(FeedbackGroup g, ref bool alert, ref bool lost, ref bool limited)
    {
        for (var i = 0; i < g.Controllers.Length; i++)
        {
            var c = g.Controllers[i];
            var reply = g.Replies[i];
            if (reply.Outcome != ReplyOutcome.Ok)
            {
                lost = true;
                Missed(c);
                continue;
            }

            if (c.ConsecutiveMisses >= _options.MissingAfterCycles)
            {
                Volatile.Write(ref c.PresentFlag, true);
                _events.Publish(new ModuleAnswersAgain(c.Id, c.Name));
            }

            c.ConsecutiveMisses = 0;
            alert |= reply.Alert && c.HardwareErrorStatus == 0; // a new alert; known ones are polled on schedule
            var block = g.Data.AsSpan(i * g.Length, g.Length);
            foreach (var m in c.MotorArray)
            {
                var at = block[(m.Config.Channel * _layout.FeedbackStride)..];
                var counts = BinaryPrimitives.ReadInt32LittleEndian(at);
                var raw = BinaryPrimitives.ReadUInt16LittleEndian(at[_layout.CurrentOffset..]);
                var pwm = BinaryPrimitives.ReadInt16LittleEndian(at[_layout.PwmOffset..]);
                var amps = m.Config.ToAmps(raw);
                m.Publish(m.Config.ToRadians(counts), amps, pwm);
                limited |= amps >= _options.CurrentLimitedFraction * m.CurrentLimitA;
            }
        }
    }
}
