using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Robot.Calibration;

/// <summary>
/// Calibrates the pots of one module's motors against their Hall counts, in steps a command or a console page drives
/// in turn:
/// <list type="number">
/// <item><see cref="Reference"/>: motors off (read back); every motor homed from the table its module holds (the robot
/// file's design curve after commissioning), so the module's position limits are roughly where the joints' are; then,
/// with the arm in its fixture pose (<see cref="PotSweepPlan.Reference"/>, confirmed by the operator), the Hall
/// counts' offset to absolute output angles.</item>
/// <item><see cref="Measure"/>: each motor swept slowly through its range and back (<see cref="PotSweepPlan.Sweep"/>),
/// pot readings recorded against absolute Hall counts.</item>
/// <item><see cref="PotCalibrationFit.Fit"/> of each motor's samples, then <see cref="Store"/>: the tables written into
/// the module's FRAM through <see cref="ParameterWriter"/> (checked, written, read back) and the motors homed from
/// them.</item>
/// <item><see cref="Verify"/>: the same sweeps again, the pot (through the new table) against the Hall position at
/// every sample; the worst disagreement per motor in degrees.</item>
/// </list>
/// While the motors are on, the module keeps every protection the robot file gave it (current limit, speed limit,
/// position limits, bus watchdog at its two stages) and every poll checks the module: Hall errors or a hold latched,
/// torque still on, and each motor following its setpoint (<see cref="PotCalibrationOptions.TrackingLimitDeg"/>); any failure, and
/// a stop request, turns the motors off (read back) before it is reported.
/// </summary>
public sealed class PotCalibrator
{
    /// <summary>What <see cref="Disarm"/>'s failure line says: the motors may still be on.</summary>
    public const string NotConfirmedOff = "turning its motors off was not confirmed";

    private static readonly ControlTable Table = ControlTable.Firmware;
    private readonly BusClient _client;
    private readonly PotSweepPlan _plan;
    private readonly PotCalibrationOptions _options;
    private readonly CancellationToken _stop;
    private readonly Action<string> _note;
    private readonly byte _id;
    private readonly int _start;
    private readonly byte[] _block;
    private readonly Dictionary<(string, int), long> _persistent = [];

    /// <summary>A calibration of <paramref name="plan"/>'s module on <paramref name="client"/>'s bus; <paramref name="note"/> is told what it recovers from, <paramref name="stop"/> ends it with the motors off.</summary>
    public PotCalibrator(BusClient client, PotSweepPlan plan, PotCalibrationOptions options, Action<string> note, CancellationToken stop)
    {
        ArgumentNullException.ThrowIfNull(note);
        _note = note;
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(plan);
        ArgumentNullException.ThrowIfNull(options);
        _client = client;
        _plan = plan;
        _options = options;
        _stop = stop;
        _id = plan.Module.Id;
        _start = Table["torque_enable"].At(0);
        var channels = plan.Motors.Max(m => m.Channel) + 1;
        _block = new byte[Table["pot_raw"].At(channels - 1) + Table["pot_raw"].Size - _start];
        Offsets = new long[plan.Motors.Count];
    }

    /// <summary>Per motor: absolute Hall counts minus the module's (known after <see cref="Reference"/>; 0 once homed from a table that <see cref="Store"/> wrote).</summary>
    public long[] Offsets { get; }

    /// <summary>Times the bus watchdog's second stage turned the motors off so far (a stalled host; each said and resumed).</summary>
    public int WatchdogStops { get; private set; }

    /// <summary>Bus holds acknowledged so far (a late host; each holds the motors for a moment).</summary>
    public int Holds { get; private set; }

    /// <summary>The module's name for lines: <c>module 1 (right shoulder)</c>.</summary>
    public string What => $"module {_id} ({_plan.Module.Name})";

    /// <summary>
    /// Motors off, each homed from the table its module holds (those with one), then the offset of each motor's Hall
    /// counts to the fixture pose, which the arm must be in now.
    /// </summary>
    /// <exception cref="IOException">The module refused, did not answer, or a motor is still on (the line names it).</exception>
    public void Reference()
    {
        Disarm();
        Poll();
        AcknowledgeStale();
        var (start, end) = Table.PersistentArea;
        var persistent = new byte[end - start];
        Require(_client.ReadMapped(_id, Table, start, persistent), "reading its parameters");
        var mask = 0;
        foreach (var m in _plan.Motors)
        {
            mask |= PotCalibrationTable.Decode(Table, persistent, start, m.Channel).IsCalibrated ? 1 << m.Channel : 0;
        }

        Home(mask);
        Poll();
        for (var i = 0; i < _plan.Motors.Count; i++)
        {
            Offsets[i] = _plan.Motors[i].ToCounts(_plan.Reference[i]) - Field("present_position", _plan.Motors[i].Channel);
        }
    }

    /// <summary>Sweeps motor <paramref name="index"/> through its range and back with the motors on; its pot readings against absolute Hall counts. The motors are off (read back) after it, whatever happens.</summary>
    /// <exception cref="IOException">A check failed (the motors are off; the line names the motor and the value).</exception>
    /// <exception cref="OperationCanceledException">Stopped (the motors are off).</exception>
    public IReadOnlyList<PotSample> Measure(int index)
    {
        var samples = new List<PotSample>();
        var channel = _plan.Motors[index].Channel;
        Run(_plan.Sweep(index), () => samples.Add(new PotSample(Field("present_position", channel) + Offsets[index], (int)Field("pot_raw", channel))));
        return samples;
    }

    /// <summary>Writes <paramref name="tables"/> (by motor index) into the module's FRAM, each value checked and read back, then homes those motors from them (their offsets become 0).</summary>
    /// <exception cref="IOException">The module refused a value, did not answer or read back something else.</exception>
    /// <exception cref="ArgumentException">A parameter rule refused a table (nothing was written).</exception>
    public IReadOnlyList<ParameterValue> Store(IReadOnlyDictionary<int, PotCalibrationTable> tables)
    {
        ArgumentNullException.ThrowIfNull(tables);
        var values = new List<ParameterValue>();
        var mask = 0;
        foreach (var (index, table) in tables)
        {
            var m = _plan.Motors[index];
            values.Add(new(Table["pot_cal_count"], m.Channel, table.Count, "points"));
            values.Add(new(Table["pot_cal_pos0"], m.Channel, table.Pos0, Deg(m, table.Pos0)));
            values.Add(new(Table["pot_cal_step"], m.Channel, table.Step, Deg(m, table.Step)));
            values.AddRange(Enumerable.Range(0, table.Count).Select(k => new ParameterValue(Table[$"pot_cal_raw{k}"], m.Channel, table.Raw[k], $"pot at {Deg(m, table.Pos0 + (k * table.Step))}")));
            mask |= 1 << m.Channel;
        }

        Disarm();
        _ = new ParameterWriter(_client, Table).WriteAll([(_id, values)]);
        Home(mask);
        foreach (var index in tables.Keys)
        {
            Offsets[index] = 0;
        }

        return values;
    }

    /// <summary>Sweeps motor <paramref name="index"/> again; the worst disagreement between its pot (through <paramref name="table"/>) and its Hall position, degrees of output.</summary>
    /// <exception cref="IOException">A check failed (the motors are off).</exception>
    /// <exception cref="OperationCanceledException">Stopped (the motors are off).</exception>
    public double Verify(int index, PotCalibrationTable table)
    {
        ArgumentNullException.ThrowIfNull(table);
        var m = _plan.Motors[index];
        var window = new Queue<long>();
        long sum = 0;
        var worst = 0.0;
        Run(_plan.Sweep(index), () =>
        {
            // A few consecutive samples averaged: the pot's noise is not a disagreement.
            var d = table.PositionAt((int)Field("pot_raw", m.Channel)) - (Field("present_position", m.Channel) + Offsets[index]);
            window.Enqueue(d);
            sum += d;
            if (window.Count > _options.VerifyWindow)
            {
                sum -= window.Dequeue();
            }

            if (window.Count == _options.VerifyWindow)
            {
                worst = Math.Max(worst, Math.Abs(m.ToRadians(sum) / window.Count) * 180 / Math.PI);
            }
        });
        return worst;
    }

    /// <summary>Motors off and the bus watchdog off, torque read back.</summary>
    /// <exception cref="IOException">The module did not answer, or a motor still reads on.</exception>
    public void Disarm()
    {
        var off = new byte[_plan.Motors.Max(m => m.Channel) + 1];
        var torque = _client.Write(_id, Table["torque_enable"].At(0), off, BusRobot.InsistingRetries);
        _ = _client.Write(_id, Table["bus_watchdog"].At(0), [0, 0], BusRobot.InsistingRetries);
        var back = new byte[off.Length];
        var read = _client.Read(_id, Table["torque_enable"].At(0), back, BusRobot.InsistingRetries);
        if (!torque.Succeeded || !read.Succeeded || back.Any(b => b != 0))
        {
            throw new IOException($"{What}: {NotConfirmedOff} (write {torque.Outcome}, read back {read.Outcome}{(read.Succeeded ? $" [{string.Join(' ', back)}]" : string.Empty)}): switch its power off");
        }
    }

    private void Arm()
    {
        var on = new byte[_plan.Motors.Max(m => m.Channel) + 1];
        foreach (var m in _plan.Motors)
        {
            on[m.Channel] = 1;
        }

        // Torque first, then the watchdog's stage 2 and stage 1 (as the robot arms a module).
        var layout = _plan.Robot.Modules;
        Require(_client.Write(_id, Table["torque_enable"].At(0), on, BusRobot.InsistingRetries), "turning its motors on");
        Require(_client.Write(_id, Table["bus_watchdog_off"].At(0), U16(layout.WatchdogOffMs), BusRobot.InsistingRetries), "arming its bus watchdog");
        Require(_client.Write(_id, Table["bus_watchdog"].At(0), U16(layout.WatchdogMs), BusRobot.InsistingRetries), "arming its bus watchdog");
    }

    /// <summary>Moves through <paramref name="waypoints"/> (absolute output angles) with the motors on, calling <paramref name="sample"/> after every poll; motors off afterwards, whatever happens.</summary>
    private void Run(IReadOnlyList<double[]> waypoints, Action sample)
    {
        try
        {
            Poll();
            Arm();
            for (var w = 1; w < waypoints.Count; w++)
            {
                Leg(waypoints[w - 1], waypoints[w], sample);
            }
        }
        finally
        {
            Disarm();
        }
    }

    private void Leg(double[] from, double[] to, Action sample)
    {
        var motors = _plan.Motors;
        var duration = motors.Select((m, i) => Math.Abs(to[i] - from[i]) / (_options.SpeedFraction * m.Motor.SpeedLimitRadS)).Max();
        var time = _client.Time;
        var begun = time.GetTimestamp();
        var behind = new long[motors.Count];
        var goals = new byte[4 * (motors.Max(m => m.Channel) + 1)];
        var holds = Holds;
        while (true)
        {
            _stop.ThrowIfCancellationRequested();
            var elapsed = time.GetElapsedTime(begun).TotalSeconds;
            if (elapsed > (_options.LegPatience * duration) + _options.SettleTime.TotalSeconds)
            {
                throw new IOException(string.Create(CultureInfo.InvariantCulture, $"{What}: a {duration:F1} s move did not get through in {elapsed:F0} s ({Holds - holds} bus holds: this host was late with a frame by more than bus_watchdog): motors off; run the calibration on a less loaded host or a faster link"));
            }

            var t = duration <= 0 ? 1 : Math.Min(1, elapsed / duration);
            for (var i = 0; i < motors.Count; i++)
            {
                var goal = motors[i].ToCounts(from[i] + ((to[i] - from[i]) * t)) - Offsets[i];
                Table["goal_position"].Encode(Math.Clamp(goal, Field("position_min", motors[i].Channel, persistent: true), Field("position_max", motors[i].Channel, persistent: true)), goals.AsSpan(4 * motors[i].Channel, 4));
            }

            var taken = _client.Write(_id, Table["goal_position"].At(0), goals);
            Poll();
            if (AcknowledgedHold())
            {
                continue; // the module held the motors where they were; the goals go again
            }

            if (Resumed())
            {
                continue; // the bus watchdog stopped the motors and they are armed again; the goals go again
            }

            // A goal's reply lost on a loaded link is harmless (the poll just read the module; the next goal goes
            // anyway); a refusal is not.
            if (taken.Outcome == ReplyOutcome.Ok)
            {
                Require(taken, "taking a goal");
            }

            Check(behind, time.GetTimestamp());
            sample();
            if (t >= 1 && (Arrived(goals) || time.GetElapsedTime(begun).TotalSeconds > duration + _options.SettleTime.TotalSeconds))
            {
                return; // there, or as near as the P loop holds it against friction
            }
        }
    }

    /// <summary>
    /// A bus hold (the watchdog's first stage: this host was late with a frame) with nothing else latched than what a
    /// hold's acknowledgement may clear (over-current, position lost) is acknowledged, as the robot does, and counted
    /// (<see cref="Holds"/>); a move they keep from getting through in <see cref="PotCalibrationOptions.LegPatience"/>
    /// times its length stops the calibration.
    /// </summary>
    private bool AcknowledgedHold()
    {
        var status = (HardwareErrors)Field("hardware_error_status", 0);
        if (!status.HasFlag(HardwareErrors.BusHold) || !(status & ~(HardwareErrors.BusHold | HardwareErrors.OverCurrent | HardwareErrors.PositionLost)).IsNone)
        {
            return false;
        }

        Holds++;
        Require(_client.Write(_id, Table["hardware_error_status"].At(0), [0], BusRobot.InsistingRetries), "acknowledging its bus hold");
        return true;
    }

    /// <summary>
    /// The bus watchdog's second stage stopped the motors (this host was silent for <c>bus_watchdog_off</c>: a stalled
    /// process, not a dead one, since it is polling again): said, acknowledged and armed again, so the sweep goes on
    /// from where the motors stopped; more than <see cref="PotCalibrationOptions.MaxWatchdogStops"/> stop the calibration.
    /// A stop can also show as motors off with nothing latched, when a hold's acknowledgement cleared the stop's bit.
    /// </summary>
    private bool Resumed()
    {
        var status = (HardwareErrors)Field("hardware_error_status", 0);
        var off = _plan.Motors.Any(m => Field("torque_enable", m.Channel) == 0);
        if (!status.HasFlag(HardwareErrors.BusWatchdog) && !(off && status.IsNone))
        {
            return false;
        }

        WatchdogStops++;
        if (WatchdogStops > _options.MaxWatchdogStops || status.HasFlag(HardwareErrors.Hall))
        {
            throw new IOException($"{What}: its bus watchdog turned the motors off {WatchdogStops} times (hardware_error_status {status}; this host was silent for more than bus_watchdog_off): motors off; run the calibration on a less loaded host");
        }

        _note($"{What}: its bus watchdog turned the motors off (this host was silent for more than {_plan.Robot.Modules.WatchdogOffMs} ms); acknowledged and armed again, the sweep goes on");
        Require(_client.Write(_id, Table["hardware_error_status"].At(0), [0], BusRobot.InsistingRetries), "acknowledging its bus watchdog");
        Arm();
        return true;
    }

    /// <summary>
    /// A bus hold or bus-watchdog stop latched before this calibration (this host went quiet at a previous stop, e.g.
    /// a stopped calibration; the motors are off now, read back) is acknowledged and said, as the robot acknowledges a
    /// hold; with anything else latched it stays, and the first check names it.
    /// </summary>
    private void AcknowledgeStale()
    {
        var status = (HardwareErrors)Field("hardware_error_status", 0);
        var stale = HardwareErrors.BusHold | HardwareErrors.BusWatchdog;
        if ((status & stale).IsNone || !(status & ~(stale | HardwareErrors.OverCurrent | HardwareErrors.PositionLost)).IsNone)
        {
            return;
        }

        Require(_client.Write(_id, Table["hardware_error_status"].At(0), [0], BusRobot.InsistingRetries), "acknowledging a bus hold latched before");
        _note($"{What}: {status & stale} latched before this calibration (this host went quiet at a previous stop; motors off, read back): acknowledged");
    }

    private bool Arrived(byte[] goals) => _plan.Motors.All(m =>
        Math.Abs(m.ToRadians(Field("present_position", m.Channel) - Table["goal_position"].Decode(goals.AsSpan(4 * m.Channel, 4)))) * 180 / Math.PI <= _options.ArrivedDeg);

    /// <summary>The module's checks after a poll: nothing latched, every motor still on and following its setpoint.</summary>
    private void Check(long[] behind, long now)
    {
        // The over-current bit says the module's current limit acted (it stays armed, and holds the current down); a
        // joint that stays blocked shows as a motor behind its setpoint. Hall errors stop the sweep: the counts are wrong.
        var status = (HardwareErrors)Field("hardware_error_status", 0);
        var stopping = HardwareErrors.Hall | HardwareErrors.BusHold;
        if (!(status & stopping).IsNone)
        {
            var motors = string.Join("; ", _plan.Motors.Select(m => $"{m.FullName}: {(HardwareErrors)Field("motor_error", m.Channel)}{BadHallStates(m)}"));
            throw new IOException($"{What}: latched {status & stopping} during the sweep ({motors}): motors off; find the cause (a Hall wire or sensor, a stalled bus) and run the calibration again");
        }

        for (var i = 0; i < _plan.Motors.Count; i++)
        {
            var m = _plan.Motors[i];
            if (Field("torque_enable", m.Channel) == 0)
            {
                throw new IOException($"{m.FullName}: its module turned the motor off during the sweep (hardware_error_status {status}): motors off; run the calibration again");
            }

            var lag = Math.Abs(m.ToRadians(Field("present_position", m.Channel) - Field("present_setpoint", m.Channel))) * 180 / Math.PI;
            behind[i] = lag <= _options.TrackingLimitDeg ? 0 : behind[i] == 0 ? now : behind[i];
            if (behind[i] != 0 && _client.Time.GetElapsedTime(behind[i], now) >= _options.TrackingTime)
            {
                throw new IOException(string.Create(CultureInfo.InvariantCulture, $"{m.FullName}: {lag:F1} deg behind its setpoint for {_options.TrackingTime.TotalSeconds:F1} s (limit {_options.TrackingLimitDeg} deg): blocked, at a hard stop, or not in the fixture pose at the start; motors off; free the joint, put the arm in its fixture pose and run the calibration again"));
            }
        }
    }

    /// <summary>The motor's invalid or skipped Hall states since its module's reset, for a line (empty when none).</summary>
    private string BadHallStates(MotorConfig m) => Field("hall_error_count", m.Channel) switch
    {
        0 => string.Empty,
        1 => ", 1 invalid or skipped Hall state",
        var n => $", {n} invalid or skipped Hall states",
    };

    private void Home(int mask)
    {
        if (mask != 0)
        {
            Require(_client.Write(_id, Table["home_request"].At(0), [(byte)mask], BusRobot.InsistingRetries), "homing from its pots");
        }
    }

    private void Poll() => Require(_client.ReadMapped(_id, Table, _start, _block, BusRobot.InsistingRetries), "reading its positions and pots");

    private long Field(string name, int channel, bool persistent = false)
    {
        var f = Table[name];
        if (!persistent)
        {
            return f.Decode(_block.AsSpan(f.At(channel) - _start, f.Size));
        }

        if (!_persistent.TryGetValue((name, channel), out var value))
        {
            value = new ParameterWriter(_client, Table).Read(_id, name, channel);
            _persistent[(name, channel)] = value;
        }

        return value;
    }

    private void Require(Reply reply, string doing)
    {
        if (!reply.Succeeded)
        {
            throw new IOException($"{What}: {doing} failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}, hardware_error_status {(HardwareErrors)Field("hardware_error_status", 0)}): check that it is connected and powered, then run the calibration again");
        }
    }

    private static byte[] U16(int value) => [(byte)value, (byte)(value >> 8)];

    private static string Deg(MotorConfig m, long counts) => string.Create(CultureInfo.InvariantCulture, $"{m.ToRadians(counts) * 180 / Math.PI:F1} deg");
}
