using System.Buffers.Binary;
using RobotControl.Bus.Client;
using RobotControl.Modules;
using RobotControl.Robot.Events;

namespace RobotControl.Robot.Bus;

/// <summary>
/// Switching a module's motors on or off: torque, then its bus watchdog (armed with the robot file's two stages when
/// on: <c>bus_watchdog_off</c>, then <c>bus_watchdog</c>, so the module never holds a stage 2 that is not after stage 1;
/// <c>bus_watchdog</c> 0 when off, which switches both stages off), each write insisting
/// (<see cref="BusRobot.InsistingRetries"/>). Bus thread only.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ModuleArming(RobotLayout layout, BusClient client, ModuleRoster roster, RobotEventStream events)
{
    /// <summary>Arms (<paramref name="on"/>) or disarms one module.</summary>
    /// <exception cref="IOException">The module refused or did not answer; the message says which write and why.</exception>
    public void Arm(RobotController c, bool on)
    {
        Span<byte> watchdog = stackalloc byte[2];
        BinaryPrimitives.WriteUInt16LittleEndian(watchdog, (ushort)(on ? layout.WatchdogMs : 0));
        Span<byte> watchdogOff = stackalloc byte[2];
        BinaryPrimitives.WriteUInt16LittleEndian(watchdogOff, (ushort)layout.WatchdogOffMs);
        Span<byte> torque = stackalloc byte[c.ChannelSpan];
        foreach (var m in c.MotorArray)
        {
            torque[m.Config.Channel] = on ? (byte)1 : (byte)0;
        }

        // Torque first, then the watchdog: a stall between the two writes must not trip a watchdog that refuses the torque.
        var t = client.Write(c.Id, layout.TorqueAddress, torque, BusRobot.InsistingRetries); // idempotent writes
        var w = on ? client.Write(c.Id, layout.WatchdogOffAddress, watchdogOff, BusRobot.InsistingRetries) : t;
        if (!on || w.Succeeded)
        {
            w = client.Write(c.Id, layout.WatchdogAddress, watchdog, BusRobot.InsistingRetries);
        }

        c.BusWatchdogMs = -1; // known again when the next status poll reads it back
        if (!w.Succeeded || !t.Succeeded)
        {
            Span<byte> status = stackalloc byte[2];
            var known = client.Read(c.Id, layout.StatusAddress, status).Succeeded;
            throw new IOException(TorqueRefusal.Describe(c.Id, c.Name, on, t, w, known ? ((HardwareErrors)status[0], status[1]) : null));
        }
    }

    /// <summary>
    /// Turns every present module's motors off, telling each even when one refuses; the first refusal is returned (a
    /// module that does not answer cannot be told: its bus watchdog stops its motors when the goals stop).
    /// </summary>
    public IOException? DisarmAll()
    {
        IOException? refused = null;
        foreach (var c in roster.Active.Controllers)
        {
            try
            {
                Arm(c, false);
            }
            catch (IOException ex)
            {
                refused ??= ex;
                events.Publish(new TorqueRefused(ex.Message));
            }
        }

        return refused;
    }
}
