using System.Buffers.Binary;
using System.Runtime;
using System.Runtime.CompilerServices;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The bus cycle and its steps: <see cref="Write"/> (goals out), <see cref="Read"/> (feedback in) and
/// <see cref="Update"/> (feedback published, modules supervised), run back to back by the bus thread
/// (<see cref="Start(Action)"/>), by <see cref="RunCycle"/>, or one by one by a virtual schedule that ticks the control loop
/// in between.
/// </summary>
public sealed partial class BusRobot
{
    /// <summary>Runs bus cycles on a thread of its own until <see cref="Stop"/> (real links).</summary>
    public void Start() => Start(static () => { });

    /// <summary>
    /// Runs bus cycles on a thread of its own until <see cref="Stop"/>; the thread first runs <paramref name="prologue"/>
    /// (e.g. to give itself real-time scheduling, which .NET threads do not inherit).
    /// </summary>
    public void Start(Action prologue)
    {
        ArgumentNullException.ThrowIfNull(prologue);
        if (_thread is not null)
        {
            return;
        }

        _stopping = false;
        _thread = new Thread(() =>
        {
            prologue();
            Loop();
        }) { IsBackground = true, Name = $"bus {Definition.Name}", Priority = ThreadPriority.AboveNormal };
        _thread.Start();
    }

    /// <summary>
    /// Methods the JIT compiled on the bus thread after its first cycle (paths first taken later: status polls, module
    /// searches, faults); known once the thread has ended (<see cref="Stop"/>).
    /// </summary>
    public long MethodsCompiledAfterFirstCycle { get; private set; }

    /// <summary>Time the bus thread spent in the JIT after its first cycle (see <see cref="MethodsCompiledAfterFirstCycle"/>).</summary>
    public TimeSpan CompileTimeAfterFirstCycle { get; private set; }

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

    /// <summary>
    /// One full-state exchange, in the bus's order: <see cref="Write"/> (every goal), <see cref="Read"/> (every
    /// position and current), <see cref="Update"/> (publish them, supervise the modules).
    /// </summary>
    public void RunCycle()
    {
        Write();
        Read();
        Update();
    }

    /// <summary>
    /// Cycle step <b>write</b>: turns the latest joint setpoints into motor goals (couplings, limits; the present
    /// positions while torque is off) and sync-writes every goal. Faults asked to be cleared are cleared first.
    /// </summary>
    public void Write()
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
        CapAndHoldGoals(dt);
        var ids = _ids;
        if (ids.Length == 0)
        {
            return;
        }

        for (var i = 0; i < _active.Length; i++)
        {
            foreach (var m in _active[i].MotorArray)
            {
                BinaryPrimitives.WriteInt32LittleEndian(_writeData.AsSpan((i * _goalLength) + (m.Config.Channel * _goalStride)), m.Config.ToCounts(_goals[m.Index]));
            }
        }

        _client.SyncWrite(_goalAddress, _goalLength, ids, _writeData);
    }

    /// <summary>
    /// Cycle step <b>read</b>: sync-reads every present module's positions and currents into the receive buffers
    /// (bus time passes). Nothing is published until <see cref="Update"/>: a reader of the port meanwhile sees the
    /// previous cycle's feedback.
    /// </summary>
    public void Read()
    {
        if (_ids.Length == 0)
        {
            return;
        }

        // One FAST BULK READ of every module's feedback (its own length) when all modules can answer it, else one
        // sync read per feedback length.
        _client.FullStateRead(_feedbackAddress, _stateIds, _stateLengths, _stateData, _stateReplies, _fastReads);
    }

    /// <summary>
    /// Cycle step <b>update</b>: publishes what <see cref="Read"/> received (joint positions through the inverse
    /// coupling, currents, missing modules) to the port, then supervises the modules: the status poll every
    /// <see cref="BusRobotOptions.StatusPollCycles"/> cycles or on an alert, the joint pots every
    /// <see cref="BusRobotOptions.PotPollCycles"/>, and a search for missing modules every
    /// <see cref="BusRobotOptions.ReprobeCycles"/>.
    /// </summary>
    public void Update()
    {
        var present = _ids.Length > 0;
        if (present)
        {
            ProcessFeedback();
        }

        var cycle = Interlocked.Increment(ref _cycles);
        if (present && cycle % _options.StatusPollCycles == 0)
        {
            PollStatus();
        }

        if (present && IsPotPollCycle(cycle))
        {
            PollPots();
        }

        if (cycle % _options.ReprobeCycles == 0)
        {
            Reprobe();
        }

        AfterUpdate?.Invoke();
    }

    // Optimized once, before the first cycle: a loop that runs for the whole session would otherwise start as quick
    // (tier-0) code and be replaced on the stack once it had looped long enough, a synchronous compile on this thread.
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Loop()
    {
        var period = (long)(_options.MinimumCyclePeriod.TotalSeconds * _time.TimestampFrequency);
        var afterFirstCycle = false;
        var compiledMethods = 0L;
        var compileTime = TimeSpan.Zero;
        while (!_stopping)
        {
            var start = _time.GetTimestamp();
            try
            {
                RunCycle();
            }
            catch (IOException ex)
            {
                Events.Enqueue(new BusError(ex.Message));
                SetLive(RobotFaults.BusDegraded, true);
                Thread.Sleep(10);
            }

            if (!afterFirstCycle)
            {
                afterFirstCycle = true;
                compiledMethods = JitInfo.GetCompiledMethodCount(currentThread: true);
                compileTime = JitInfo.GetCompilationTime(currentThread: true);
            }

            while (period > 0 && _time.GetTimestamp() - start < period && !_stopping)
            {
                Thread.SpinWait(50);
            }
        }

        if (afterFirstCycle)
        {
            MethodsCompiledAfterFirstCycle = JitInfo.GetCompiledMethodCount(currentThread: true) - compiledMethods;
            CompileTimeAfterFirstCycle = JitInfo.GetCompilationTime(currentThread: true) - compileTime;
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
                    Events.Enqueue(new ModuleStoppedAnswering(c.Id, c.Name));
                }

                continue;
            }

            if (c.ConsecutiveMisses >= _options.MissingAfterCycles)
            {
                Volatile.Write(ref c.PresentFlag, true);
                Events.Enqueue(new ModuleAnswersAgain(c.Id, c.Name));
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
}
