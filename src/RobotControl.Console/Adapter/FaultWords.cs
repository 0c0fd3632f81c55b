using System.Globalization;
using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// A safety trip in plain words for the surgeon, e.g. "left forearm module stopped answering — motors off", built
/// from the trip and the robot file's arm, module and joint names; the raw detail goes along.
/// </summary>
internal static class FaultWords
{
    /// <summary>The trip as the surgeon's view shows it; <paramref name="seconds"/> is its session time.</summary>
    public static FaultView Describe(SafetyTrip trip, RobotDefinition robot, double seconds)
    {
        ArgumentNullException.ThrowIfNull(trip);
        ArgumentNullException.ThrowIfNull(robot);
        var who = Subject(trip.Joint, robot);
        var c = CultureInfo.InvariantCulture;
        var what = trip.Check switch
        {
            SafetyCheck.ModuleSilent => $"{who} module stopped answering",
            SafetyCheck.OverCurrent => $"{who} motor drew too much current",
            SafetyCheck.TrackingError => $"{who} could not follow its command",
            SafetyCheck.PotMismatch => $"{who} position sensors disagree",
            SafetyCheck.NonFinite => who.Length == 0 || trip.Joint == "setpoint" ? "the control software sent an invalid position" : $"{who} reported an invalid value",
            SafetyCheck.HostStall => string.Create(c, $"the control computer paused for {trip.Measured:0} ms"),
            SafetyCheck.DeadlineMiss => string.Create(c, $"the control loop fell {trip.Measured:0} ms behind ({trip.Joint})"),
            SafetyCheck.MasterJump => $"{who} hand controller jumped",
            SafetyCheck.ModuleFault => "a motor module reported a fault (watchdog or hardware error)",
            SafetyCheck.Operator => "emergency stop pressed",
            SafetyCheck.MasterTimeout => $"{who} hand controller stopped sending",
            SafetyCheck.PluginFault => $"{trip.Joint} of the control graph failed",
            _ => trip.Check.Name(),
        };
        var action = trip.Soft
            ? "arms holding, press the pedal again"
            : trip.Action == SafeState.Hold ? "arms holding" : "motors off";
        return new FaultView(seconds, $"{Capitalise(what)} — {action}", trip.Check.Name(), trip.Joint, ArmOf(trip.Joint, robot), trip.Measured, trip.Limit, trip.Unit, trip.Action.Name());
    }

    /// <summary>The arm a subject names ("right.forearm", "right.elbow", "right" -> "right"), or empty.</summary>
    private static string ArmOf(string name, RobotDefinition robot)
    {
        var dot = name.IndexOf('.', StringComparison.Ordinal);
        var arm = dot < 0 ? name : name[..dot];
        return robot.Arms.Any(a => a.Name == arm) ? arm : string.Empty;
    }

    /// <summary>"right.forearm" -> "right forearm", "right.elbow" -> "right elbow", "right" -> "right"; unknown names as they are.</summary>
    private static string Subject(string name, RobotDefinition robot)
    {
        if (string.IsNullOrEmpty(name))
        {
            return string.Empty;
        }

        var arm = ArmOf(name, robot);
        if (arm.Length == 0)
        {
            return name;
        }

        return name.Length == arm.Length ? arm : $"{arm} {name[(arm.Length + 1)..].Replace('_', ' ')}";
    }

    private static string Capitalise(string text) => text.Length == 0 ? text : char.ToUpperInvariant(text[0]) + text[1..];
}
