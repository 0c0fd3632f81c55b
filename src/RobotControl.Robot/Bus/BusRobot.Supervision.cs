using System.Buffers.Binary;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>Module supervision: status poll, resets, watchdog, faults cleared, modules found again.</summary>
public sealed partial class BusRobot
{
    /// <summary>Bytes the status poll reads per module: <c>hardware_error_status</c>, <c>reset_cause</c>, <c>bus_watchdog</c> (u16).</summary>
    private const int StatusPollLength = 4;

    private void PollStatus()
    {
        if (_ids.Length == 0)
        {
            return;
        }

        _client.SyncRead(_statusAddress, StatusPollLength, _ids, _statusData, _statusReplies);
        for (var i = 0; i < _active.Length; i++)
        {
            if (_statusReplies[i].Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            var c = _active[i];
            var at = StatusPollLength * i;
            var status = (HardwareErrors)_statusData[at];
            var cause = _statusData[at + 1];
            c.HardwareErrorStatus = status.Value;
            c.BusWatchdogMs = BinaryPrimitives.ReadUInt16LittleEndian(_statusData.AsSpan(at + 2, 2)); // before a reset re-arms it
            if (cause != 0)
            {
                HandleReset(c, cause, status);
            }

            if (status.HasAny(HardwareErrors.BusWatchdog) && (_latchedFaults & (int)RobotFaults.WatchdogTripped) == 0)
            {
                SetLatched(RobotFaults.WatchdogTripped);
                Events.Enqueue(new WatchdogTripped(c.Id, c.Name));
                EnterFault($"module {c.Id} \"{c.Name}\": bus watchdog tripped");
            }

            if (status.HasAny(HardwareErrors.Hall | HardwareErrors.PotMismatch) && (_latchedFaults & (int)RobotFaults.HardwareError) == 0)
            {
                SetLatched(RobotFaults.HardwareError);
                Events.Enqueue(new HardwareErrorLatched(c.Id, c.Name, status));
                EnterFault($"module {c.Id} \"{c.Name}\": hardware error {status}");
            }

            // The firmware latches over-current whenever a current limit engages: that is the limit doing its job
            // (CurrentLimited), not a fault. Acknowledge it when nothing else is latched, so the alert flag clears.
            if (status.HasAny(HardwareErrors.OverCurrent))
            {
                SetLive(RobotFaults.CurrentLimited, true);
                if ((status & ~(HardwareErrors.OverCurrent | HardwareErrors.PositionLost)).IsNone)
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
        var why = _resetCauses.TryGetValue(cause, out var name) ? name : $"cause {cause}";
        var resumed = !status.HasAny(HardwareErrors.PositionLost);
        var mismatch = status.HasAny(HardwareErrors.PotMismatch);
        Events.Enqueue(new ModuleResetEvent(c.Id, c.Name, why, resumed, mismatch));
        _ = _client.Write(c.Id, _resetCauseAddress, [0]);
        if (!mismatch && _torqueEnabled)
        {
            Arm(c, true);
        }
        else if (mismatch)
        {
            SetLatched(RobotFaults.HardwareError);
            EnterFault($"module {c.Id} \"{c.Name}\" reset and its position disagrees with the pot");
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
        var t = WriteArming(c.Id, _torqueAddress, torque);
        var w = WriteArming(c.Id, _watchdogAddress, watchdog);
        c.BusWatchdogMs = -1; // known again when the next status poll reads it back
        if (!w.Succeeded || !t.Succeeded)
        {
            Span<byte> status = stackalloc byte[2];
            var known = _client.Read(c.Id, _statusAddress, status).Succeeded;
            throw new IOException(TorqueRefusal.Describe(c.Id, c.Name, on, t, w, known ? ((HardwareErrors)status[0], status[1]) : null));
        }
    }

    /// <summary>
    /// Retries of a transaction that must get through: the arming writes and a stop's torque-off and read-back
    /// (12 transactions in all, up to about 10 ms at 1 Mbaud). Switching the motors on or off is set-up, not the cycle,
    /// and one stalled reply must not leave a robot half-armed or a stop unverified (a pty simulator in another process
    /// missed whole transactions under load). A refusal (an answer with an error) is final.
    /// </summary>
    public const int InsistingRetries = 11;

    private Reply WriteArming(byte id, ushort address, ReadOnlySpan<byte> data) =>
        _client.Write(id, address, data, InsistingRetries); // torque and watchdog writes are idempotent

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
                    Events.Enqueue(new TorqueRefused(ex.Message));
                }
            }
        }

        Volatile.Write(ref _latchedFaults, 0);
        if (_state.Current == RobotState.Fault)
        {
            _state.MoveTo(_torqueEnabled ? RobotState.Enabled : MotorsOffState, "faults cleared");
        }
    }

    /// <summary>A module stopped its motors or latched an error: the robot is in <see cref="RobotState.Fault"/> until faults are cleared or the motors turned off.</summary>
    private void EnterFault(string reason)
    {
        if (_state.CanMoveTo(RobotState.Fault))
        {
            _state.MoveTo(RobotState.Fault, reason);
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
            Events.Enqueue(new ModuleAnswersAgain(c.Id, c.Name));
            RebuildActive();
        }
    }
}
