using System.Buffers.Binary;
using RobotControl.Bus.Client;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Events;

namespace RobotControl.Robot.Bus;

/// <summary>
/// Watches the modules after each publish, on the bus thread: the status poll (latched errors, resets, the armed
/// watchdog) every <see cref="BusRobotOptions.StatusPollCycles"/> cycles or on a new alert; the joint pots every
/// <see cref="BusRobotOptions.PotPollCycles"/>; one module's per-motor detail (torque read back, motor errors) every
/// <see cref="BusRobotOptions.DetailPollCycles"/>, in turn; a search for missing modules every
/// <see cref="BusRobotOptions.ReprobeCycles"/>. Resets re-arm a module that was driven; latched errors and tripped
/// watchdogs put the robot in its fault state; a bus hold (the watchdog's first stage) is counted
/// (<see cref="Holding"/>) and reported, and acknowledged only when asked (<see cref="AcknowledgeHold"/>). Written by
/// the bus thread alone; what it finds is published on the controllers and motors and in the event stream.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ModuleSupervisor(RobotLayout layout, BusClient client, ModuleRoster roster, BusRobotOptions options, RobotEventStream events, RobotFaultFlags faults, RobotLifecycle life, ModuleArming arming)
{
    /// <summary>The latched bits a hold's acknowledgement may clear along with it (the poll acknowledges the other two itself).</summary>
    private static readonly HardwareErrors Acknowledgeable = HardwareErrors.BusHold | HardwareErrors.OverCurrent | HardwareErrors.PositionLost;

    private readonly byte[] _detail = new byte[layout.Controllers.Max(c => c.ChannelSpan)];
    private int _detailNext;
    private int _holding;

    /// <summary>Present modules whose status, as last read, shows a bus hold (any thread reads it).</summary>
    public int Holding => Volatile.Read(ref _holding);

    /// <summary>The module work of cycle <paramref name="cycle"/> (after the feedback is published).</summary>
    public void AfterPublish(long cycle, bool alert)
    {
        var present = roster.Active.Any;
        if (present && (alert || cycle % options.StatusPollCycles == 0))
        {
            PollStatus();
        }

        if (present && options.PotPollCycles > 0 && cycle % options.PotPollCycles == options.PotPollCycles / 2)
        {
            PollPots();
        }

        if (present && options.DetailPollCycles > 0 && cycle % options.DetailPollCycles == options.DetailPollCycles / 4)
        {
            PollDetail();
        }

        if (cycle % options.ReprobeCycles == 0)
        {
            Reprobe();
        }
    }

    /// <summary>Clears latched faults here and in the modules, re-arming them if torque was on (bus thread, at a write).</summary>
    public void ClearInModules()
    {
        foreach (var c in roster.Active.Controllers)
        {
            _ = client.Write(c.Id, layout.StatusAddress, [0, 0]);
            c.HardwareErrorStatus = 0;
            if (life.TorqueEnabled)
            {
                try
                {
                    arming.Arm(c, true);
                }
                catch (IOException ex)
                {
                    events.Publish(new TorqueRefused(ex.Message));
                }
            }
        }

        faults.ClearLatched();
        CountHolds();
        life.LeaveFault("faults cleared");
    }

    /// <summary>
    /// Acknowledges module <paramref name="c"/>'s bus hold (bus thread, at a write, before its goals) if its status shows
    /// one and nothing else latched but over-current or position lost: <c>hardware_error_status</c> 0, and it follows
    /// the goals again. A module with another latched error keeps holding until faults are cleared
    /// (<see cref="ClearInModules"/>), so an acknowledgement never wipes a fault. True when acknowledged.
    /// </summary>
    public bool AcknowledgeHold(RobotController c)
    {
        var status = (HardwareErrors)c.HardwareErrorStatus;
        if (!status.HasAny(HardwareErrors.BusHold) || !(status & ~Acknowledgeable).IsNone || !client.Write(c.Id, layout.StatusAddress, [0]).Succeeded)
        {
            return false;
        }

        c.HardwareErrorStatus = 0;
        events.Publish(new HoldAcknowledged(c.Id, c.Name));
        CountHolds();
        return true;
    }

    /// <summary>
    /// A module's reset cause from before the host connected is history, not a fault: it is kept as the module's last
    /// reset (so a page says why it last started, e.g. power-on or its watchdog) and cleared in the module.
    /// </summary>
    public void AcknowledgeStartup()
    {
        Span<byte> two = stackalloc byte[2];
        foreach (var c in roster.Active.Controllers)
        {
            if (!client.Read(c.Id, layout.StatusAddress, two).Succeeded)
            {
                continue;
            }

            c.HardwareErrorStatus = two[0];
            if (two[1] != 0)
            {
                c.LastResetCause = two[1];
                c.LastResetBeforeConnect = true;
                _ = client.Write(c.Id, layout.ResetCauseAddress, [0]);
            }
        }

        CountHolds();
    }

    private void PollStatus()
    {
        var active = roster.Active;
        client.SyncRead(layout.StatusAddress, RobotLayout.StatusPollLength, active.Ids, active.StatusData, active.StatusReplies);
        for (var i = 0; i < active.Controllers.Length; i++)
        {
            if (active.StatusReplies[i].Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            var c = active.Controllers[i];
            var at = RobotLayout.StatusPollLength * i;
            var status = (HardwareErrors)active.StatusData[at];
            var cause = active.StatusData[at + 1];
            var held = c.BusHold;
            c.HardwareErrorStatus = status.Value;
            if (c.BusHold && !held)
            {
                events.Publish(new ModuleHolding(c.Id, c.Name));
            }
            c.BusWatchdogMs = BinaryPrimitives.ReadUInt16LittleEndian(active.StatusData.AsSpan(at + 2, 2)); // before a reset re-arms it
            if (cause != 0)
            {
                HandleReset(c, cause, status);
            }

            if (status.HasAny(HardwareErrors.BusWatchdog) && !faults.IsLatched(RobotFaults.WatchdogTripped))
            {
                faults.Latch(RobotFaults.WatchdogTripped);
                events.Publish(new WatchdogTripped(c.Id, c.Name));
                life.EnterFault($"module {c.Id} \"{c.Name}\": bus watchdog tripped");
            }

            if (status.HasAny(HardwareErrors.Hall | HardwareErrors.PotMismatch) && !faults.IsLatched(RobotFaults.HardwareError))
            {
                faults.Latch(RobotFaults.HardwareError);
                events.Publish(new HardwareErrorLatched(c.Id, c.Name, status));
                life.EnterFault($"module {c.Id} \"{c.Name}\": hardware error {status}");
            }

            // The firmware latches over-current whenever a current limit engages: that is the limit doing its job
            // (CurrentLimited), not a fault. Acknowledge it when nothing else is latched, so the alert flag clears.
            if (status.HasAny(HardwareErrors.OverCurrent))
            {
                faults.SetLive(RobotFaults.CurrentLimited, true);
                if ((status & ~(HardwareErrors.OverCurrent | HardwareErrors.PositionLost)).IsNone)
                {
                    _ = client.Write(c.Id, layout.StatusAddress, [0]);
                    c.HardwareErrorStatus = 0;
                }
            }
        }

        CountHolds();
    }

    private void CountHolds()
    {
        var n = 0;
        foreach (var c in roster.Active.Controllers)
        {
            n += c.BusHold ? 1 : 0;
        }

        Volatile.Write(ref _holding, n);
    }

    private void HandleReset(RobotController c, byte cause, HardwareErrors status)
    {
        c.Resets++;
        c.LastResetCause = cause;
        c.LastResetBeforeConnect = false;
        faults.Latch(RobotFaults.ModuleReset);
        var why = layout.ResetCauses.TryGetValue(cause, out var name) ? name : $"cause {cause}";
        var resumed = !status.HasAny(HardwareErrors.PositionLost);
        var mismatch = status.HasAny(HardwareErrors.PotMismatch);
        events.Publish(new ModuleResetEvent(c.Id, c.Name, why, resumed, mismatch));
        _ = client.Write(c.Id, layout.ResetCauseAddress, [0]);
        if (!mismatch && life.TorqueEnabled)
        {
            arming.Arm(c, true);
        }
        else if (mismatch)
        {
            faults.Latch(RobotFaults.HardwareError);
            life.EnterFault($"module {c.Id} \"{c.Name}\" reset and its position disagrees with the pot");
        }
    }

    /// <summary>One sync read of every module's <c>pot_raw</c>, each motor's pot position through its calibration.</summary>
    private void PollPots()
    {
        var active = roster.Active;
        client.SyncRead(layout.PotAddress, layout.PotLength, active.Ids, active.PotData, active.PotReplies);
        for (var i = 0; i < active.Controllers.Length; i++)
        {
            if (active.PotReplies[i].Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            foreach (var m in active.Controllers[i].MotorArray)
            {
                m.PublishPot(BinaryPrimitives.ReadUInt16LittleEndian(active.PotData.AsSpan((i * layout.PotLength) + (m.Config.Channel * layout.PotStride))));
            }
        }
    }

    /// <summary>The next present module's torque (read back) and per-motor errors: two reads, one module per poll.</summary>
    private void PollDetail()
    {
        var active = roster.Active.Controllers;
        if (active.Length == 0)
        {
            return;
        }

        var c = active[_detailNext++ % active.Length];
        var span = _detail.AsSpan(0, c.ChannelSpan);
        var torque = client.Read(c.Id, layout.TorqueAddress, span).Succeeded;
        foreach (var m in c.MotorArray)
        {
            m.PublishTorque(torque ? span[m.Config.Channel] != 0 : null);
        }

        var errors = client.Read(c.Id, layout.MotorErrorAddress, span).Succeeded;
        foreach (var m in c.MotorArray)
        {
            m.PublishErrors(errors ? (HardwareErrors)span[m.Config.Channel] : null);
        }
    }

    private void Reprobe()
    {
        foreach (var c in layout.Controllers)
        {
            if (c.Present || client.Ping(c.Id, out var info).Outcome != ReplyOutcome.Ok)
            {
                continue;
            }

            c.ModelNumber = info.ModelNumber;
            c.FirmwareVersion = info.FirmwareVersion;
            c.ConsecutiveMisses = 0;
            Volatile.Write(ref c.PresentFlag, true);
            events.Publish(new ModuleAnswersAgain(c.Id, c.Name));
            roster.Rebuild();
        }
    }
}
