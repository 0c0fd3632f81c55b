using RobotControl.Definitions.Model;

namespace RobotControl.Host.Safety;

/// <summary>One trip.</summary>
/// <param name="Timestamp">When it was detected, on the supervisor's clock.</param>
/// <param name="Check">Which check.</param>
/// <param name="Joint">The motor or module concerned (e.g. <c>right.elbow</c>), or empty.</param>
/// <param name="Measured">The value measured (unit in <paramref name="Unit"/>).</param>
/// <param name="Limit">The limit it crossed.</param>
/// <param name="Unit">Unit of the value and the limit.</param>
/// <param name="Action">The safe state taken.</param>
/// <param name="Soft">A soft trip: the arms held and the run level went back to PEDAL_UP, not to E_STOP.</param>
public sealed record SafetyTrip(long Timestamp, SafetyCheck Check, string Joint, double Measured, double Limit, string Unit, SafeState Action, bool Soft = false)
{
    /// <summary>The trip in one line: the check, what it concerns, the value measured against its limit, the safe state (e.g. <c>module_silent left.forearm: 52.3 ms (limit 50 ms): torque_off</c>, <c>host_stall: 23.1 ms (limit 10 ms): hold, back to PEDAL_UP</c>).</summary>
    public override string ToString()
    {
        var who = Joint.Length == 0 ? Check.Name() : $"{Check.Name()} {Joint}";
        var value = Unit.Length == 0 ? string.Empty : string.Create(System.Globalization.CultureInfo.InvariantCulture, $": {Measured:0.###} {Unit} (limit {Limit:0.###} {Unit})");
        return $"{who}{value}: {Action.Name()}{(Soft ? ", back to PEDAL_UP" : string.Empty)}";
    }
}
