using System.Globalization;
using RobotControl.Bus.Protocol;
using RobotControl.Modules;
using RobotControl.Robot.Bus;

namespace RobotControl.Host.Safety;

/// <summary>
/// The supervisor's check before it arms (homing, motors on, PEDAL_UP): no present module has a protection switched
/// off. For every motor the robot file drives, each persistent field whose 0 switches a protection off (the control
/// table's <c>zero_disables</c>: the current limit, the speed limit) is read from its module and judged by the one rule
/// (<see cref="ParameterRules.ProtectionOff"/>); the first one off is named, with its module, motor and value, and the
/// supervisor does not arm. The bus watchdog is not read here: arming writes the robot file's (refused at load when 0)
/// and <see cref="ModuleChecks"/> checks it as read back while the motors are on.
/// </summary>
[WrittenBy(RobotThread.Bus)]
internal sealed class ProtectionsAtArming(BusRobot robot)
{
    private static readonly ControlTableField[] Protections =
        [.. ControlTable.Firmware.Fields.Where(f => f.ZeroDisables is not null && f.Persistent && f.Count > 1)];

    /// <summary>The first protection switched off in a present module, as one line; null when none is. Reads the modules.</summary>
    public string? FirstSwitchedOff()
    {
        foreach (var c in robot.Controllers.Where(c => c.Present))
        {
            if (FirstSwitchedOff(c) is { } off)
            {
                return off;
            }
        }

        return null;
    }

    /// <summary>
    /// The first protection switched off in module <paramref name="c"/>. A module that does not answer is left to
    /// homing and arming, which cannot get past it either and name it.
    /// </summary>
    private string? FirstSwitchedOff(RobotController c)
    {
        foreach (var m in c.Motors)
        {
            foreach (var field in Protections)
            {
                long value;
                try
                {
                    value = robot.ReadParameter(c.Id, field.Name, m.Config.Channel);
                }
                catch (IOException)
                {
                    return null;
                }

                if (ParameterRules.ProtectionOff(field, value) is { } off)
                {
                    return string.Create(CultureInfo.InvariantCulture, $"module {c.Id} \"{c.Name}\", motor {m.Config.FullName} (channel {m.Config.Channel}): {field.Name}[{m.Config.Channel}] is {value}: {off}");
                }
            }
        }

        return null;
    }
}
