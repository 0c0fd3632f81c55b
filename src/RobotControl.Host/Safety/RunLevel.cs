namespace RobotControl.Host.Safety;

/// <summary>The safety supervisor's run levels, lowest first (Raven-II's, plus homing).</summary>
public enum RunLevel
{
    /// <summary>Stopped after a trip or an operator command: motors held or off; leaving needs an operator reset.</summary>
    EStop,

    /// <summary>Powered, positions not yet trusted (not homed); nothing moves.</summary>
    Init,

    /// <summary>Homing from the joint pots; the only motion allowed outside <see cref="PedalDown"/>.</summary>
    Homing,

    /// <summary>Enabled, holding position: goals frozen at the measured positions, teleoperation ignored.</summary>
    PedalUp,

    /// <summary>Teleoperation drives the arms (every goal under the step cap).</summary>
    PedalDown,
}

/// <summary>Names of the run levels as reports and the console write them.</summary>
public static class RunLevelNames
{
    /// <summary>E_STOP, INIT, HOMING, PEDAL_UP, PEDAL_DOWN.</summary>
    public static string Name(this RunLevel level) => level switch
    {
        RunLevel.EStop => "E_STOP",
        RunLevel.Init => "INIT",
        RunLevel.Homing => "HOMING",
        RunLevel.PedalUp => "PEDAL_UP",
        RunLevel.PedalDown => "PEDAL_DOWN",
        _ => level.ToString(),
    };
}

/// <summary>One run-level change.</summary>
/// <param name="Timestamp">When, on the supervisor's clock (<see cref="TimeProvider.GetTimestamp"/>).</param>
/// <param name="From">Level before.</param>
/// <param name="To">Level after.</param>
/// <param name="Source">Who asked: <c>operator</c>, <c>pedal</c>, <c>session</c>, <c>cli</c>, or the check that tripped.</param>
/// <param name="Reason">Why.</param>
public sealed record RunLevelTransition(long Timestamp, RunLevel From, RunLevel To, string Source, string Reason);
