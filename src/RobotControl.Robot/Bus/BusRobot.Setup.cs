using System.Buffers.Binary;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>Module setup: discovery, parameters, torque.</summary>
public sealed partial class BusRobot
{
    private ParameterWriter? _parameterWriter;

    /// <summary>
    /// Broadcast-pings the bus and compares what answers with the robot file: missing, unknown and mismatched
    /// modules are listed (each problem also once in <see cref="Events"/>); present ones take part in the cycles.
    /// Moves the robot to <see cref="RobotState.Discovered"/>.
    /// </summary>
    /// <exception cref="InvalidOperationException">The motors are on (turn them off first) or homing runs.</exception>
    public DiscoveryReport Discover()
    {
        _state.Require("discovery", "turn the motors off first (EnableTorque(false))", RobotState.Disabled, RobotState.Discovered, RobotState.Homed);
        var found = new PingInfo[253];
        var n = _client.Discover(found);
        var answered = found.AsSpan(0, n).ToArray();
        var present = new List<RobotController>();
        var missing = new List<RobotController>();
        var mismatched = new List<string>();
        var mismatchedIds = new HashSet<byte>();
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
                mismatchedIds.Add(c.Id);
                mismatched.Add($"id {c.Id} \"{c.Name}\": model number {c.ModelNumber}, expected {model} (not a RobotControl motor module)");
                ok = false;
            }
            else if (_client.Read(c.Id, motorCount, one).Succeeded && one[0] < c.ChannelSpan)
            {
                mismatchedIds.Add(c.Id);
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
        var report = new DiscoveryReport(present, missing.Where(m => !mismatchedIds.Contains(m.Id)).ToArray(), unknown, mismatched);
        foreach (var problem in report.Problems)
        {
            Events.Enqueue(new DiscoveryProblemEvent(problem));
        }

        SetLive(RobotFaults.ModuleMissing, report.Missing.Count > 0 || mismatched.Count > 0);
        _state.MoveTo(RobotState.Discovered, $"discovery: {report.Present.Count} of {_controllers.Length} modules as configured");
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

    /// <summary>
    /// Writes the robot file's parameters into every present module's FRAM through the one parameter path
    /// (<see cref="ParameterWriter.WriteAll"/>): all are checked before any is written, then read back.
    /// </summary>
    /// <returns>How many values were written.</returns>
    /// <exception cref="ArgumentException">A value breaks the control table's rules; nothing was written.</exception>
    /// <exception cref="IOException">A module refused a value, did not answer or read back something else.</exception>
    public int WriteParameters() =>
        Parameters.WriteAll([.. _active.Select(c => (c.Id, ModuleParameters.For(Definition, c.Definition, _table)))]);

    /// <summary>
    /// Writes one persistent parameter of one motor (or module-wide field) through the one parameter path
    /// (<see cref="ParameterWriter.Write"/>: checked, written, read back).
    /// </summary>
    /// <exception cref="ArgumentException">The value breaks the control table's rules; nothing was written.</exception>
    /// <exception cref="IOException">The module refused the value, did not answer or read back something else.</exception>
    public long WriteParameter(byte moduleId, string field, int motor, long value) => Parameters.Write(moduleId, field, motor, value);

    /// <summary>Reads one control-table value.</summary>
    /// <exception cref="IOException">The module does not answer.</exception>
    public long ReadParameter(byte moduleId, string field, int motor = 0) => Parameters.Read(moduleId, field, motor);

    /// <summary>
    /// Turns the motors on (arming each module's bus watchdog) or off. Turning on first makes every setpoint the
    /// present position, so nothing moves until the control loop or a manual command says so.
    /// </summary>
    /// <exception cref="IOException">A module refuses (e.g. its watchdog error is latched: clear faults first).</exception>
    /// <exception cref="InvalidOperationException">
    /// On: the robot was not discovered, is homing, or is in <see cref="RobotState.Fault"/> (clear faults first).
    /// Off: homing runs.
    /// </exception>
    public void EnableTorque(bool on)
    {
        if (on)
        {
            _state.Require("turning the motors on", "discover the modules first, and clear faults if any", RobotState.Discovered, RobotState.Homed, RobotState.Enabled);
        }
        else
        {
            _state.Require("turning the motors off", "wait for homing to end", RobotState.Disabled, RobotState.Discovered, RobotState.Homed, RobotState.Enabled, RobotState.Fault);
        }

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

        IOException? refused = null;
        foreach (var c in _active)
        {
            try
            {
                Arm(c, on);
            }
            catch (IOException ex) when (!on)
            {
                refused ??= ex; // off: every other module is still told
            }
        }

        if (on)
        {
            _state.MoveTo(RobotState.Enabled, "motors on");
        }
        else if (_state.Current != RobotState.Disabled)
        {
            _state.MoveTo(MotorsOffState, "motors off");
        }

        if (refused is not null)
        {
            throw refused; // after the move: the others are off, and the robot knows it
        }
    }

    /// <summary>Clears latched faults here and in the modules (hardware errors, watchdog) and re-enables torque if it was on.</summary>
    public void ClearFaults() => _clearRequested = true;

    /// <summary>The one parameter path on this robot's bus (made on first use).</summary>
    private ParameterWriter Parameters => _parameterWriter ??= new ParameterWriter(_client, _table);

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
        _statusData = new byte[_ids.Length * StatusPollLength];
        _statusReplies = new Reply[_ids.Length];
        ResizePotBuffers();
    }
}
