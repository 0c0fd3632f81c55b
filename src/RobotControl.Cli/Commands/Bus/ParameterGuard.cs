using System.Globalization;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// The checks <c>params set</c> makes before anything is stored (see <see cref="ParameterRules"/>): each value against
/// the control table, confirmation for the fields that change how the module is reached (<c>id</c>; <c>baud_rate</c> is
/// changed on the whole bus by <see cref="BaudChange"/>), and the cross-field rules on the module's table as read from it
/// with the new values applied.
/// </summary>
internal static class ParameterGuard
{
    /// <summary>Checks one write; throws with the reason when it must not happen.</summary>
    /// <exception cref="ArgumentException">The value, field, motor or confirmation is wrong.</exception>
    /// <exception cref="IOException">The module does not answer.</exception>
    public static void CheckOne(BusClient client, ControlTable table, byte id, ControlTableField field, int motor, long value, bool confirmed)
    {
        if (ParameterRules.CheckValue(field, value) is { } problem)
        {
            throw new ArgumentException($"--value: {problem}");
        }

        if (motor >= field.Count)
        {
            throw new ArgumentException(field.Count == 1
                ? $"--motor: {field.Name} is one value per module; give --motor 0 (or leave it out)"
                : $"--motor: {field.Name} has motors 0..{field.Count - 1}");
        }

        // A new ID makes the module answer elsewhere (a baud change never comes here: BaudChange moves the whole bus).
        if (field.Name == "id" && !confirmed)
        {
            throw new ArgumentException("--field id: the module will answer only at the new ID after this write; add --yes to confirm");
        }

        if (client.Ping(id, out _).Outcome != ReplyOutcome.Ok)
        {
            throw new IOException($"--module {id}: no module answers at this ID on {client.Link.Description}; nothing was written");
        }

        if (field.Persistent && field.Count > 1)
        {
            var block = ReadPersistent(client, table, id);
            var problems = ParameterRules.CheckMotor(Values(table, block, new() { [(field.Name, motor)] = value }), motor, field.Name);
            if (problems.Count > 0)
            {
                throw new ArgumentException($"module {id}: {string.Join("; ", problems)}; nothing was written");
            }
        }
    }

    /// <summary>Checks every value the robot file implies for module <paramref name="id"/> before any is written.</summary>
    /// <exception cref="ArgumentException">A value or rule fails (all problems, in one line).</exception>
    /// <exception cref="IOException">The module's table cannot be read.</exception>
    public static void CheckAll(BusClient client, ControlTable table, byte id, IReadOnlyList<ParameterValue> values)
    {
        var problems = values.Select(p => ParameterRules.CheckValue(p.Field, p.Value)).OfType<string>().ToList();
        var block = ReadPersistent(client, table, id);
        var changes = values.ToDictionary(p => (p.Field.Name, p.Motor), p => p.Value);
        foreach (var motor in values.Where(p => p.Field.Count > 1).Select(p => p.Motor).Distinct())
        {
            problems.AddRange(ParameterRules.CheckMotor(Values(table, block, changes), motor));
        }

        if (problems.Count > 0)
        {
            throw new ArgumentException($"module {id}: the robot file's values break the module's rules: {string.Join("; ", problems)}; nothing was written");
        }
    }

    private static byte[] ReadPersistent(BusClient client, ControlTable table, byte id)
    {
        var (start, end) = table.PersistentArea;
        var block = new byte[end - start];
        var reply = client.ReadMapped(id, table, start, block);
        return reply.Succeeded
            ? block
            : throw new IOException(string.Create(CultureInfo.InvariantCulture, $"module {id}: reading its parameters failed ({reply.Outcome}, {StatusErrors.Describe(reply.Error)}); nothing was written"));
    }

    private static Func<string, int, long> Values(ControlTable table, byte[] block, Dictionary<(string, int), long> changes) =>
        (name, motor) => changes.TryGetValue((name, motor), out var v)
            ? v
            : table[name].Decode(block.AsSpan(table[name].At(motor) - table.PersistentArea.Start, table[name].Size));
}
