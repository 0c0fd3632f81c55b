using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;

namespace RobotControl.Modules;

/// <summary>
/// The one path by which the host stores a module parameter (the command line's <c>params set</c>, the console's
/// parameter edits and the robot file's values all come here): the value is checked against its field
/// (<see cref="ParameterRules.CheckValue"/>) and, for a per-motor persistent field, the motor's cross-field rules are
/// checked on the module's persistent block as read from the bus with the new value applied
/// (<see cref="ParameterRules.CheckMotor"/>); only then is it written, and it is read back. Each failure is an
/// exception with one line that is the same whoever asked: <see cref="ArgumentException"/> when a rule refuses the
/// value (nothing was written), <see cref="IOException"/> when the module refuses it, does not answer or reads back
/// something else.
/// </summary>
public sealed class ParameterWriter
{
    private readonly BusClient _client;
    private readonly ControlTable _table;

    /// <summary>A writer on <paramref name="client"/>'s bus for modules with <paramref name="table"/>.</summary>
    public ParameterWriter(BusClient client, ControlTable table)
    {
        ArgumentNullException.ThrowIfNull(client);
        ArgumentNullException.ThrowIfNull(table);
        _client = client;
        _table = table;
    }

    /// <summary>
    /// The checks that need no module: the field is writable, has motor <paramref name="motor"/>, and accepts
    /// <paramref name="value"/> (a value that switches a protection off only with <paramref name="allowProtectionOff"/>).
    /// </summary>
    /// <exception cref="ArgumentException">Why not, naming the field; nothing was written.</exception>
    public static void CheckValue(ControlTableField field, int motor, long value, bool allowProtectionOff = false)
    {
        ArgumentNullException.ThrowIfNull(field);
        if (motor < 0 || motor >= field.Count)
        {
            throw Refused(field.Count == 1 ? $"{field.Name} is one value per module, motor {motor} given" : $"{field.Name} has motors 0..{field.Count - 1}, motor {motor} given");
        }

        if (ParameterRules.CheckValue(field, value, allowProtectionOff) is { } problem)
        {
            throw Refused(problem);
        }
    }

    /// <summary>
    /// Every check of writing <paramref name="value"/> into <paramref name="field"/>[<paramref name="motor"/>] of module
    /// <paramref name="id"/>: <see cref="CheckValue"/>, then for a per-motor persistent field the motor's rules on the
    /// module's table as it would be after the write.
    /// </summary>
    /// <exception cref="ArgumentException">A check fails; nothing was written.</exception>
    /// <exception cref="IOException">The module's table cannot be read; nothing was written.</exception>
    public void Check(byte id, string field, int motor, long value, bool allowProtectionOff = false)
    {
        var f = Field(field);
        CheckValue(f, motor, value, allowProtectionOff);
        if (f.Persistent && f.Count > 1)
        {
            var block = new PersistentBlock(ReadPersistent(id), _table, new() { [(f.Name, motor)] = value });
            var problems = ParameterRules.CheckMotor(block.Value, motor, f.Name);
            if (problems.Count > 0)
            {
                throw Refused($"module {id}: {string.Join("; ", problems)}");
            }
        }
    }

    /// <summary>
    /// Checks (<see cref="Check"/>), writes and reads back one value; returns the value read back. A value that
    /// switches a protection off is written only with <paramref name="allowProtectionOff"/>.
    /// </summary>
    /// <exception cref="ArgumentException">A check fails; nothing was written.</exception>
    /// <exception cref="IOException">The module refused the value, did not answer, or read back something else.</exception>
    public long Write(byte id, string field, int motor, long value, bool allowProtectionOff = false)
    {
        Check(id, field, motor, value, allowProtectionOff);
        var f = _table[field];
        Put(id, f, motor, value);
        var back = Read(id, field, motor);
        return back == value
            ? back
            : throw new IOException(string.Create(CultureInfo.InvariantCulture, $"module {id}: {Name(f, motor)} reads back {back} after writing {value}"));
    }

    /// <summary>
    /// Writes many values into many modules: every value of every module is checked first (each against its field,
    /// and all of a module's motors' rules on its table with all of its new values applied), then they are written
    /// and each module's persistent block is read back and compared.
    /// </summary>
    /// <returns>How many values were written.</returns>
    /// <exception cref="ArgumentException">A check fails (every problem of the first such module, in one line); nothing was written.</exception>
    /// <exception cref="IOException">A module's table cannot be read, a module refused a value or reads back something else.</exception>
    public int WriteAll(IReadOnlyList<(byte Id, IReadOnlyList<ParameterValue> Values)> modules)
    {
        ArgumentNullException.ThrowIfNull(modules);
        foreach (var (id, values) in modules)
        {
            CheckAll(id, values);
        }

        var count = 0;
        foreach (var (id, values) in modules)
        {
            foreach (var p in values)
            {
                Put(id, p.Field, p.Motor, p.Value);
                count++;
            }

            var block = new PersistentBlock(ReadPersistent(id, "its values were written but not read back"), _table, []);
            var differ = values.Where(p => p.Field.Persistent && block.Value(p.Field.Name, p.Motor) != p.Value)
                .Select(p => string.Create(CultureInfo.InvariantCulture, $"{Name(p.Field, p.Motor)} reads back {block.Value(p.Field.Name, p.Motor)} after writing {p.Value}"))
                .ToList();
            if (differ.Count > 0)
            {
                throw new IOException($"module {id}: {string.Join("; ", differ)}");
            }
        }

        return count;
    }

    /// <summary>Reads one control-table value.</summary>
    /// <exception cref="IOException">The module does not answer.</exception>
    public long Read(byte id, string field, int motor = 0)
    {
        var f = _table[field];
        Span<byte> bytes = stackalloc byte[4];
        var reply = _client.Read(id, f.At(motor), bytes[..f.Size]);
        return reply.Outcome == ReplyOutcome.Ok
            ? f.Decode(bytes)
            : throw new IOException($"module {id}: reading {Name(f, motor)} failed ({reply.Outcome})");
    }

    private static ArgumentException Refused(string problem) => new($"{problem}; nothing was written");

    private static string Name(ControlTableField field, int motor) => string.Create(CultureInfo.InvariantCulture, $"{field.Name}[{motor}]");

    private void CheckAll(byte id, IReadOnlyList<ParameterValue> values)
    {
        var problems = values.Select(p => ParameterRules.CheckValue(p.Field, p.Value)).OfType<string>().ToList();
        var block = new PersistentBlock(ReadPersistent(id), _table, values.ToDictionary(p => (p.Field.Name, p.Motor), p => p.Value));
        foreach (var motor in values.Where(p => p.Field.Count > 1).Select(p => p.Motor).Distinct())
        {
            problems.AddRange(ParameterRules.CheckMotor(block.Value, motor));
        }

        if (problems.Count > 0)
        {
            throw Refused($"module {id}: {string.Join("; ", problems)}");
        }
    }

    private ControlTableField Field(string name) =>
        _table.Contains(name) ? _table[name] : throw new ArgumentException($"the control table has no field '{name}'; nothing was written");

    private void Put(byte id, ControlTableField field, int motor, long value)
    {
        Span<byte> bytes = stackalloc byte[4];
        field.Encode(value, bytes);
        var reply = _client.Write(id, field.At(motor), bytes[..field.Size]);
        if (!reply.Succeeded)
        {
            throw new IOException(Failed(id, field, motor, value, reply));
        }
    }

    /// <summary>The line for a write of <paramref name="value"/> into <paramref name="field"/>[<paramref name="motor"/>] of module <paramref name="id"/> that <paramref name="reply"/> says failed, with what to do when the module locked it.</summary>
    public static string Failed(byte id, ControlTableField field, int motor, long value, Reply reply)
    {
        ArgumentNullException.ThrowIfNull(field);
        var locked = field.Persistent && StatusErrors.Number(reply.Error) == StatusError.Access ? ": the persistent area is locked while torque is on, turn torque off first" : string.Empty;
        return string.Create(CultureInfo.InvariantCulture, $"module {id}: writing {Name(field, motor)} = {value} failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}){locked}");
    }

    /// <summary>Module <paramref name="id"/>'s persistent area; <paramref name="then"/> says, on failure, what became of the values.</summary>
    private byte[] ReadPersistent(byte id, string then = "nothing was written")
    {
        var (start, end) = _table.PersistentArea;
        var block = new byte[end - start];
        var reply = _client.ReadMapped(id, _table, start, block);
        return reply.Succeeded
            ? block
            : throw new IOException(string.Create(CultureInfo.InvariantCulture, $"module {id}: reading its parameters failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}); {then}"));
    }

    /// <summary>A module's persistent values as read, with <c>changes</c> applied on top.</summary>
    private sealed class PersistentBlock(byte[] block, ControlTable table, Dictionary<(string, int), long> changes)
    {
        public long Value(string name, int motor) => changes.TryGetValue((name, motor), out var v)
            ? v
            : table[name].Decode(block.AsSpan(table[name].At(motor) - table.PersistentArea.Start, table[name].Size));
    }
}
