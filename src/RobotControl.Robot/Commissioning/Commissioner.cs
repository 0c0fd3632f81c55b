using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Definitions.Model;
using RobotControl.Modules;

namespace RobotControl.Robot.Commissioning;

/// <summary>
/// Commissions a unit module by module: finds each factory-fresh module at the control table's default ID as the
/// operator connects it, gives it its robot-file ID (checked by a ping there), writes every parameter the robot file
/// defines through the one parameter path (<see cref="ParameterWriter"/>, each verified by read-back), sets the baud
/// when the file's differs from the factory's, and records the module in the unit file. Modules the unit file holds
/// are done; any other is (re)done from the start, so a stop at any point loses nothing. The module whose robot-file ID
/// is the default ID comes last: until then a fresh module at that ID is the one being commissioned. A stop
/// (<paramref name="stop"/>, the console's STOP) ends it between two bus transactions; commissioning never turns a
/// motor on.
/// </summary>
public sealed class Commissioner(CommissionSetup setup, BusClient client, TextWriter output, CancellationToken stop = default)
{
    private static readonly ControlTable Table = ControlTable.Firmware;
    private static readonly byte FactoryId = (byte)Table["id"].Default;
    private static readonly int FactoryBaud = ModuleParameters.BaudFromCode((int)Table["baud_rate"].Default);

    /// <summary>Commissions every module not yet in the unit file; returns the exit code.</summary>
    /// <exception cref="IOException">A module refused a write, went silent or the operator's input ended (one line naming the module and what to do).</exception>
    /// <exception cref="ArgumentException">A robot-file value is refused by the parameter rules (naming the module, parameter and value).</exception>
    public int Run()
    {
        ArgumentNullException.ThrowIfNull(setup);
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(output);
        var modules = setup.Robot.Modules.Modules;
        var order = modules.Where(m => m.Id != FactoryId).Concat(modules.Where(m => m.Id == FactoryId)).ToList();
        for (var k = 0; k < order.Count; k++)
        {
            var module = order[k];
            var what = $"module {k + 1} of {order.Count} ({module.Name}, id {module.Id})";
            Stopped(what);
            if (setup.Unit.Module(module.Id) is not null)
            {
                output.WriteLine($"{what}: done ({setup.UnitPath})");
                continue;
            }

            if (module.Id != FactoryId && client.Ping(module.Id, out _).Outcome == ReplyOutcome.Ok)
            {
                output.WriteLine($"{what}: answers at its ID already (a commissioning stopped halfway): writing its parameters again");
            }
            else
            {
                FindFresh(what);
                GiveId(module, what);
            }

            var (values, info) = WriteParameters(module, what);
            Record(module, what, values, info);
        }

        output.WriteLine($"unit {setup.Unit.Unit} commissioned: {order.Count} modules ({setup.UnitPath})");
        return 0;
    }

    /// <summary>Waits until exactly one module answers at the default ID (the operator connects it).</summary>
    private void FindFresh(string what)
    {
        output.WriteLine(setup.Poll
            ? $"connect {what}: waiting for it at id {FactoryId}"
            : $"connect {what}, then press Enter");
        var collisions = 0;
        var told = string.Empty;
        while (true)
        {
            Stopped(what);
            if (!setup.Poll && setup.Operator.ReadLine() is null)
            {
                Stopped(what);
                throw new IOException($"stopped before {what} was connected (no more input); run commission again to continue from it");
            }

            var found = Probe();
            collisions = found == Presence.Two ? collisions + 1 : 0;
            if (found == Presence.One)
            {
                return;
            }

            var line = found == Presence.Two && collisions >= 2
                ? $"two modules answer at ID {FactoryId}: unplug all but one"
                : found == Presence.None && !setup.Poll ? $"no module answers at id {FactoryId}: check that {what} is plugged in and powered" : string.Empty;
            if (line.Length > 0 && (line != told || !setup.Poll))
            {
                output.WriteLine(setup.Poll ? line : line + ", then press Enter");
                told = line;
            }

            if (setup.Poll)
            {
                setup.Time.Delay(TimeSpan.FromMilliseconds(200), stop);
            }
        }
    }

    /// <summary>Ends the run when it was asked to stop (before <paramref name="what"/> was recorded).</summary>
    private void Stopped(string what)
    {
        if (stop.IsCancellationRequested)
        {
            throw new IOException($"stopped before {what} was recorded (commissioning turns no motor on); run commission again to continue from it");
        }
    }

    /// <summary>One ping at the default ID: no answer, one clean answer, or garbled ones (two modules talking at once).</summary>
    private Presence Probe()
    {
        var before = client.CrcErrors + client.StrayFrames + client.DiscardedBytes;
        var reply = client.Ping(FactoryId, out _);
        var garbled = client.CrcErrors + client.StrayFrames + client.DiscardedBytes != before || reply.Outcome == ReplyOutcome.BadLength;
        return garbled ? Presence.Two : reply.Outcome == ReplyOutcome.Ok ? Presence.One : Presence.None;
    }

    /// <summary>Writes the module's robot-file ID; the module answers from it at once, so the write's own reply is not awaited. Checked by a ping at the new ID.</summary>
    private void GiveId(ModuleDefinition module, string what)
    {
        if (module.Id == FactoryId)
        {
            return;
        }

        // The module answers from its new ID at once, so this write's own reply times out (expected); a reply at the
        // default ID is a refusal (e.g. torque on: the persistent area is locked).
        var reply = client.Write(FactoryId, Table["id"].At(0), [module.Id]);
        if (reply.Outcome == ReplyOutcome.Ok && !reply.Succeeded)
        {
            throw new IOException($"commissioning {module.Name}: {ParameterWriter.Failed(FactoryId, Table["id"], 0, module.Id, reply)}; the module is not recorded: fix it and run commission again");
        }

        for (var attempt = 0; attempt < 5; attempt++)
        {
            setup.Time.Delay(TimeSpan.FromMilliseconds(20));
            if (client.Ping(module.Id, out _).Outcome == ReplyOutcome.Ok)
            {
                output.WriteLine($"{what}: now answers at id {module.Id}");
                return;
            }
        }

        throw new IOException($"{what}: written ID {module.Id} but nothing answers there; power-cycle the module and run commission again");
    }

    /// <summary>Writes the module's parameters, reads its identity (at the factory baud), then moves it to the robot file's baud if that differs.</summary>
    private (List<ParameterValue> Values, PingInfo Info) WriteParameters(ModuleDefinition module, string what)
    {
        var values = ModuleParameters.For(setup.Robot, module, Table).Where(p => p.Field.Name != "baud_rate").ToList();
        try
        {
            _ = new ParameterWriter(client, Table).WriteAll([(module.Id, values)]);
        }
        catch (Exception ex) when (ex is ArgumentException or IOException)
        {
            throw new IOException($"commissioning {module.Name}: {ex.Message}; the module is not recorded: fix it and run commission again", ex);
        }

        if (client.Ping(module.Id, out var info).Outcome != ReplyOutcome.Ok)
        {
            throw new IOException($"{what}: silent after its parameters were written; check its power and run commission again");
        }

        var baud = setup.Robot.Modules.BaudRate;
        if (baud != FactoryBaud)
        {
            // Last, as it cuts the module off at the factory baud: written, then checked at the new baud.
            var code = ModuleParameters.BaudCode(baud);
            _ = client.Write(module.Id, Table["baud_rate"].At(0), [(byte)code]);
            if (!setup.AnswersAt(baud, module.Id))
            {
                throw new IOException($"commissioning {module.Name}: set to {baud} baud but it does not answer at that baud; power-cycle it and run commission again");
            }

            values.Add(new ParameterValue(Table["baud_rate"], 0, code, $"{baud} baud"));
        }

        return (values, info);
    }

    private void Record(ModuleDefinition module, string what, List<ParameterValue> values, PingInfo info)
    {
        setup.Unit.Modules.Add(new UnitModule
        {
            Id = module.Id,
            Name = module.Name,
            ModelNumber = info.ModelNumber,
            FirmwareVersion = info.FirmwareVersion,
            Parameters = new(values.ToDictionary(p => UnitFile.Key(p.Field, p.Motor), p => p.Value)),
        });
        setup.Unit.Save(setup.UnitPath, setup.Time.GetUtcNow());
        output.WriteLine($"{what}: firmware {info.FirmwareVersion}, {values.Count} parameters written and verified; recorded in {setup.UnitPath}");
    }

    private enum Presence
    {
        None,
        One,
        Two,
    }
}

/// <summary>What a commissioning runs with: the robot file, the unit file and its path, the operator's input or polling, the clock, and a check of a module at another baud.</summary>
public sealed record CommissionSetup(RobotDefinition Robot, UnitFile Unit, string UnitPath, TextReader Operator, bool Poll, CommissionClock Time, Func<int, byte, bool> AnswersAt);

/// <summary>The commissioning's time: the date it records and the waits between polls.</summary>
public sealed class CommissionClock(TimeProvider time)
{
    /// <summary>Now, UTC.</summary>
    public DateTimeOffset GetUtcNow() => time.GetUtcNow();

    /// <summary>Waits <paramref name="duration"/> on the clock, or until <paramref name="stop"/> (then it returns at once).</summary>
    public void Delay(TimeSpan duration, CancellationToken stop = default) => Task.Delay(duration, time, stop).ContinueWith(_ => { }, TaskScheduler.Default).GetAwaiter().GetResult();
}
