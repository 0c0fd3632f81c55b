using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// What <c>params set</c> checks before a write that only the command line needs: the motor option, confirmation for
/// the fields that change how the module is reached (<c>id</c>; <c>baud_rate</c> is changed on the whole bus by
/// <see cref="BaudChange"/>), and that the module answers. A value that switches a protection off passes only with
/// <c>--allow-protection-off</c> (the rule and its wording are <see cref="ParameterRules"/>'). The value and the cross-field rules are the one parameter
/// path's (<see cref="ParameterWriter"/>), with the same wording as the console's.
/// </summary>
internal static class ParameterGuard
{
    /// <summary>Checks one write; throws with the reason when it must not happen.</summary>
    /// <exception cref="ArgumentException">The value, field, motor or confirmation is wrong.</exception>
    /// <exception cref="IOException">The module does not answer.</exception>
    /// <param name="client">The bus.</param>
    /// <param name="id">The module.</param>
    /// <param name="field">The field written.</param>
    /// <param name="motor">Its motor.</param>
    /// <param name="value">The value.</param>
    /// <param name="consent">--yes (a new ID), --allow-protection-off (a value that switches a protection off).</param>
    public static void CheckOne(BusClient client, byte id, ControlTableField field, int motor, long value, (bool Confirmed, bool ProtectionOff) consent)
    {
        if (motor >= field.Count)
        {
            throw new ArgumentException(field.Count == 1
                ? $"--motor: {field.Name} is one value per module; give --motor 0 (or leave it out)"
                : $"--motor: {field.Name} has motors 0..{field.Count - 1}");
        }

        ParameterWriter.CheckValue(field, motor, value, consent.ProtectionOff); // before the bus: a wrong value is wrong on any module

        // A new ID makes the module answer elsewhere (a baud change never comes here: BaudChange moves the whole bus).
        if (field.Name == "id" && !consent.Confirmed)
        {
            throw new ArgumentException("--field id: the module will answer only at the new ID after this write; add --yes to confirm");
        }

        if (client.Ping(id, out _).Outcome != ReplyOutcome.Ok)
        {
            throw new IOException($"--module {id}: no module answers at this ID on {client.Link.Description}; nothing was written");
        }
    }
}
