using System.Text.Json;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Session;

/// <summary>
/// What the modules said after a session switched their motors off: every configured module is read back (torque of
/// every channel, latched hardware errors), so that a stop is known to have left the robot safe, not assumed to. The
/// writes and reads of a stop ask again when no answer comes (<see cref="BusRobot.InsistingRetries"/>): a module is
/// reported unreachable only after that many tries.
/// </summary>
/// <param name="Modules">Modules read back.</param>
/// <param name="TorqueOn">Modules that still report torque on (each as <c>id "name"</c>).</param>
/// <param name="LatchedErrors">Modules with a latched hardware error, and which (e.g. a tripped bus watchdog).</param>
/// <param name="Unreachable">Modules that did not answer the read-back.</param>
public sealed record StopCheck(int Modules, IReadOnlyList<string> TorqueOn, IReadOnlyList<string> LatchedErrors, IReadOnlyList<string> Unreachable)
{
    /// <summary>How long after the first stop request (a signal, the console closing, the session's stop) the motors were read back (null: not timed).</summary>
    public TimeSpan? AfterRequest { get; init; }

    /// <summary>Null when the control loop ended at the stop; else what its thread was stuck in (a plug-in's tick that did not return).</summary>
    public string? LoopHung { get; init; }

    /// <summary>Why the link itself failed during the stop (an adapter unplugged, the other end of a pty gone), or null.</summary>
    public string? LinkFailure { get; init; }

    /// <summary>True when every module answered and reports torque off on every channel.</summary>
    public bool TorqueOff => TorqueOn.Count == 0 && Unreachable.Count == 0;

    /// <summary>The read-back in words: <c>torque off on all 6 modules (read back)</c>, or where torque is not confirmed off.</summary>
    public string Summary => TorqueOff
        ? $"torque off on all {Modules} modules (read back)"
        : $"torque NOT confirmed off: on at [{string.Join(", ", TorqueOn)}], no answer from [{string.Join(", ", Unreachable)}]{(LinkFailure is null ? string.Empty : $"; the link failed: {LinkFailure} (the modules' bus watchdogs switch their motors off)")}";

    /// <summary>
    /// Writes the read-back as the reports' <c>"stop"</c> object: <c>modules</c>, <c>torque_off</c>, <c>torque_on</c>,
    /// <c>latched_errors</c>, <c>unreachable</c>, <c>read_back_after_ms</c> (from the first stop request), <c>loop_hung</c> (a run's <c>report.json</c> and the console's session report).
    /// </summary>
    public void Write(Utf8JsonWriter w)
    {
        ArgumentNullException.ThrowIfNull(w);
        w.WriteStartObject("stop");
        w.WriteNumber("modules", Modules);
        w.WriteBoolean("torque_off", TorqueOff);
        WriteList(w, "torque_on", TorqueOn);
        WriteList(w, "latched_errors", LatchedErrors);
        WriteList(w, "unreachable", Unreachable);
        if (AfterRequest is { } after)
        {
            w.WriteNumber("read_back_after_ms", Math.Round(after.TotalMilliseconds, 1));
        }

        w.WriteString("loop_hung", LoopHung);
        w.WriteString("link_failure", LinkFailure);
        w.WriteEndObject();
    }

    /// <summary>
    /// Switches the motors off (through the robot's state machine; if a module refuses, by writing torque and watchdog
    /// off to every configured module directly) and reads every module back. A module whose only latched error is its
    /// bus watchdog's first-stage hold, with its motors read back off, has the hold cleared: it means nothing once the
    /// motors are off, and left latched it would refuse the next run's torque-on.
    /// </summary>
    public static StopCheck TorqueOffAndVerify(BusRobot robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        var table = ControlTable.Firmware;
        var torque = table["torque_enable"];
        var watchdog = table["bus_watchdog"];
        var status = table["hardware_error_status"];
        string? linkFailure = null;
        try
        {
            robot.EnableTorque(false);
        }
        catch (Exception ex) when (ex is IOException or InvalidOperationException)
        {
            linkFailure = ex is IOException ? ex.Message : null;
            var zeros = new byte[Span(torque)];
            foreach (var c in robot.Controllers)
            {
                try
                {
                    _ = robot.Client.Write(c.Id, torque.At(0), zeros, BusRobot.InsistingRetries);
                    _ = robot.Client.Write(c.Id, watchdog.At(0), zeros.AsSpan(0, watchdog.Size), BusRobot.InsistingRetries);
                }
                catch (IOException failure)
                {
                    linkFailure ??= failure.Message; // the link itself failed (an adapter unplugged): the read-back below says which modules are unreachable
                }
            }
        }

        var on = new List<string>();
        var latched = new List<string>();
        var unreachable = new List<string>();
        var channels = new byte[Span(torque)];
        var error = new byte[1];
        foreach (var c in robot.Controllers)
        {
            var who = $"{c.Id} \"{c.Name}\"";
            if (!ReadBack(robot, c.Id, torque.At(0), channels, ref linkFailure).Succeeded || ReadBack(robot, c.Id, status.At(0), error, ref linkFailure).Outcome != ReplyOutcome.Ok)
            {
                unreachable.Add(who);
                continue;
            }

            if (channels.Any(b => b != 0))
            {
                on.Add(who);
            }

            if (error[0] == (byte)HardwareErrors.BusHold && channels.All(b => b == 0) && robot.Client.Write(c.Id, status.At(0), [0], BusRobot.InsistingRetries).Succeeded)
            {
                continue; // only the first watchdog stage's hold, with the motors off: it means nothing now, and left latched it would refuse the next torque-on
            }

            if (error[0] != 0)
            {
                latched.Add($"{who}: {new HardwareErrors(error[0])}");
            }
        }

        return new StopCheck(robot.Controllers.Count, on, latched, unreachable) { LinkFailure = linkFailure };
    }

    private static void WriteList(Utf8JsonWriter w, string name, IReadOnlyList<string> items)
    {
        w.WriteStartArray(name);
        foreach (var item in items)
        {
            w.WriteStringValue(item);
        }

        w.WriteEndArray();
    }

    /// <summary>One insisting read of the stop's read-back; a link that fails (an adapter unplugged) is no answer.</summary>
    private static Reply ReadBack(BusRobot robot, byte id, ushort address, Span<byte> data, ref string? linkFailure)
    {
        try
        {
            return robot.Client.Read(id, address, data, BusRobot.InsistingRetries);
        }
        catch (IOException ex)
        {
            linkFailure ??= ex.Message;
            return new Reply(ReplyOutcome.Timeout, 0);
        }
    }

    private static int Span(ControlTableField field) => ((field.Count - 1) * field.Stride) + field.Size;
}
