using System.Collections.Concurrent;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Recording;

/// <summary>
/// What the recorder reads off the loop thread, on its writer thread: the supervisor's run-level transitions and
/// trips (each once, as they appear), the operator commands handed to it, the bus's running totals and the modules'
/// status (every <see cref="RecordingOptions.SlowEvery"/> of loop time). The same sources the run report and the
/// console's status page read.
/// </summary>
internal sealed class SessionSources(SafetySupervisor supervisor, BusRobot bus, RecordingChannels channels, ulong startNs, ConcurrentQueue<(string Who, string What)> commands)
{
    private int _levels;
    private int _trips;

    /// <summary>Writes what happened since the last call: transitions, trips, commands at their times; nothing else.</summary>
    public void Events(ulong nowNs)
    {
        var history = supervisor.HistoryCount > _levels ? supervisor.History : []; // the copy (and its lock, which the bus thread takes to move) only when there is news
        for (; _levels < history.Count; _levels++)
        {
            var h = history[_levels];
            var json = channels.Begin();
            json.WriteStartObject();
            json.WriteString("from", h.From.Name());
            json.WriteString("to", h.To.Name());
            json.WriteString("source", h.Source);
            json.WriteString("reason", h.Reason);
            json.WriteEndObject();
            channels.Write(channels.RunLevel, At(supervisor.Seconds(h.Timestamp), nowNs));
        }

        var trips = supervisor.TripCount > _trips ? supervisor.Trips : [];
        for (; _trips < trips.Count; _trips++)
        {
            var t = trips[_trips];
            var json = channels.Begin();
            json.WriteStartObject();
            json.WriteString("check", t.Check.Name());
            json.WriteString("joint", t.Joint);
            RecordingChannels.Number(json, "measured", t.Measured);
            RecordingChannels.Number(json, "limit", t.Limit);
            json.WriteString("unit", t.Unit);
            json.WriteString("action", t.Action.ToString());
            json.WriteBoolean("soft", t.Soft);
            json.WriteEndObject();
            channels.Write(channels.Trips, At(supervisor.Seconds(t.Timestamp), nowNs));
        }

        while (commands.TryDequeue(out var command))
        {
            var json = channels.Begin();
            json.WriteStartObject();
            json.WriteString("who", command.Who);
            json.WriteString("what", command.What);
            json.WriteEndObject();
            channels.Write(channels.Operator, nowNs);
        }
    }

    /// <summary>Writes the bus's running totals and the modules' status at <paramref name="nowNs"/>.</summary>
    public void Status(ulong nowNs)
    {
        var totals = bus.Client.Totals(bus.Controllers.Select(c => c.Id));
        var json = channels.Begin();
        json.WriteStartObject();
        json.WriteNumber("cycles", bus.Cycles);
        json.WriteNumber("frames", totals.Frames);
        json.WriteNumber("crc_errors", totals.CrcErrors);
        json.WriteNumber("timeouts", totals.Timeouts);
        json.WriteNumber("retries", totals.Retries);
        json.WriteNumber("late_replies", bus.Client.LateReplies);
        json.WriteEndObject();
        channels.Write(channels.Bus, nowNs);
        json = channels.Begin();
        json.WriteStartObject();
        foreach (var c in bus.Controllers)
        {
            json.WriteStartObject(RecordingChannels.Id(c.Id));
            json.WriteBoolean("present", c.Present);
            json.WriteNumber("hardware_error_bits", c.HardwareErrorStatus);
            json.WriteEndObject();
        }

        json.WriteEndObject();
        channels.Write(channels.Modules, nowNs);
    }

    /// <summary>The log time of a supervisor time (seconds from the run's origin; before it, the recording's start), never after <paramref name="nowNs"/>.</summary>
    private ulong At(double seconds, ulong nowNs) => Math.Min(nowNs, startNs + (ulong)Math.Max(0, Math.Round(seconds * 1e9)));
}
