using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Control;
using RobotControl.Robot.Control.States;
using RobotControl.Robot.Events;
using RobotControl.Robot.States;

namespace RobotControl.Robot.Bus;

/// <summary>
/// Module set-up, on the bus thread (between cycles): discovery, parameters, the motors on and off, reboots. Each
/// action is refused in states it does not fit (<see cref="RobotLifecycle"/>).
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class RobotSetup(RobotLayout layout, BusClient client, ModuleRoster roster, RobotEventStream events, RobotFaultFlags faults, RobotLifecycle life, ModuleArming arming, ModuleSupervisor supervisor, FeedbackExchange feedback, SetpointExchange setpoints, GoalSeed seed)
{
    /// <summary>The source of the moves set-up makes.</summary>
    private const string Source = "setup";

    private readonly ParameterWriter _parameters = new(client, layout.Table);

    private StateMachine<RobotState> State => life.Machine;

    public DiscoveryReport Discover()
    {
        State.Require("discovery", "turn the motors off first (EnableTorque(false))", RobotState.Disabled, RobotState.Discovered, RobotState.Homed);
        var found = new PingInfo[253];
        var n = client.Discover(found);
        var answered = found.AsSpan(0, n).ToArray();
        var present = new List<RobotController>();
        var missing = new List<RobotController>();
        var mismatched = new List<string>();
        var mismatchedIds = new HashSet<byte>();
        var model = (ushort)layout.Table["model_number"].Default;
        var motorCount = layout.Table["motor_count"].At(0);
        Span<byte> one = stackalloc byte[1];
        foreach (var c in layout.Controllers)
        {
            var hit = Array.FindIndex(answered, p => p.Id == c.Id);
            if (hit < 0 && client.Ping(c.Id, out var info).Outcome == ReplyOutcome.Ok)
            {
                // A ping of its own gets past one corrupted broadcast reply.
                answered = [.. answered, info];
                hit = answered.Length - 1;
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
            else if (client.Read(c.Id, motorCount, one).Succeeded && one[0] < c.ChannelSpan)
            {
                mismatchedIds.Add(c.Id);
                mismatched.Add($"id {c.Id} \"{c.Name}\": drives {one[0]} motors, the robot file uses channels up to {c.ChannelSpan - 1}");
                ok = false;
            }

            Volatile.Write(ref c.PresentFlag, ok);
            c.ConsecutiveMisses = 0;
            (ok ? present : missing).Add(c);
        }

        var unknown = answered.Where(p => layout.Controllers.All(c => c.Id != p.Id)).ToArray();
        roster.Rebuild();
        supervisor.AcknowledgeStartup();
        var report = new DiscoveryReport(present, [.. missing.Where(m => !mismatchedIds.Contains(m.Id))], unknown, mismatched);
        foreach (var problem in report.Problems)
        {
            events.Publish(new DiscoveryProblemEvent(problem));
        }

        faults.SetLive(RobotFaults.ModuleMissing, report.Missing.Count > 0 || mismatched.Count > 0);
        State.MoveTo(RobotState.Discovered, Source, $"discovery: {report.Present.Count} of {layout.Controllers.Length} modules as configured");
        return report;
    }

    public IReadOnlyList<ParameterMismatch> CheckParameters()
    {
        var result = new List<ParameterMismatch>();
        var (start, end) = layout.Table.PersistentArea;
        var block = new byte[end - start];
        foreach (var c in roster.Active.Controllers)
        {
            var reply = client.ReadMapped(c.Id, layout.Table, start, block);
            if (!reply.Succeeded)
            {
                throw new IOException($"module {c.Id} \"{c.Name}\": reading its parameters failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)})");
            }

            foreach (var p in ModuleParameters.For(layout.Definition, c.Definition, layout.Table))
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

    /// <summary>The robot file's values into every present module's FRAM, through the one parameter path: all checked before any is written, then read back.</summary>
    public int WriteParameters() =>
        _parameters.WriteAll([.. roster.Active.Controllers.Select(c => (c.Id, ModuleParameters.For(layout.Definition, c.Definition, layout.Table)))]);

    /// <summary>One persistent value through the one parameter path (<see cref="ParameterWriter.Write"/>: checked, written, read back).</summary>
    public long WriteParameter(byte moduleId, string field, int motor, long value, bool allowProtectionOff) => _parameters.Write(moduleId, field, motor, value, allowProtectionOff);

    public long ReadParameter(byte moduleId, string field, int motor) => _parameters.Read(moduleId, field, motor);

    public Reply TryReadParameter(byte moduleId, string field, int motor, out long value, int? retries = null)
    {
        var f = layout.Table[field];
        Span<byte> bytes = stackalloc byte[4];
        var reply = retries is { } n ? client.Read(moduleId, f.At(motor), bytes[..f.Size], n) : client.Read(moduleId, f.At(motor), bytes[..f.Size]);
        value = reply.Outcome == ReplyOutcome.Ok ? f.Decode(bytes) : 0;
        return reply;
    }

    public void EnableTorque(bool on)
    {
        if (on)
        {
            State.Require("turning the motors on", "discover the modules first, and clear faults if any", RobotState.Discovered, RobotState.Homed, RobotState.Enabled);
            feedback.ReadPresentPositions();
            seed.Take(setpoints, feedback, layout); // the next write starts the goals from the positions just read
            foreach (var m in layout.Motors)
            {
                m.ReleaseManual();
            }

            foreach (var c in roster.Active.Controllers)
            {
                arming.Arm(c, true);
            }

            State.MoveTo(RobotState.Enabled, Source, "motors on");
            return;
        }

        State.Require("turning the motors off", "wait for homing to end", RobotState.Disabled, RobotState.Discovered, RobotState.Homed, RobotState.Enabled, RobotState.Fault);
        var refused = arming.DisarmAll();
        life.MotorsOff(Source, "motors off");
        if (refused is not null)
        {
            throw refused; // after the move: the others are off, and the robot knows it
        }
    }

    /// <summary>The motors off at a write, asked for by a supervisor: never throws (a refusal is an event).</summary>
    public void TorqueOffAtWrite(string reason)
    {
        if (life.State is RobotState.Homing or RobotState.Disabled)
        {
            return;
        }

        _ = arming.DisarmAll();
        life.MotorsOff("emergency hold", reason);
    }

    public Reply Reboot(byte moduleId)
    {
        State.Require($"rebooting module {moduleId}", "turn the motors off first", RobotState.Disabled, RobotState.Discovered, RobotState.Homed);
        return client.Reboot(moduleId);
    }
}
