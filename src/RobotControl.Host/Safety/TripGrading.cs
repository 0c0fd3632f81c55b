using RobotControl.Definitions.Model;

namespace RobotControl.Host.Safety;

/// <summary>
/// How a trip is taken, by its check and what it measured: the check's safe state from the robot file, except that a
/// silence (<see cref="SafetyCheck.HostStall"/>, <see cref="SafetyCheck.DeadlineMiss"/>,
/// <see cref="SafetyCheck.ModuleSilent"/>) as long as the modules' torque-off stage or longer takes the motors off
/// (the modules have switched them off already); shorter, and for the master's checks
/// (<see cref="SafetyCheck.MasterTimeout"/>, <see cref="SafetyCheck.MasterJump"/>), a safe state of hold makes it soft
/// (hold, back to PEDAL_UP). Immutable: looked up once per check, no dictionary on a trip's path.
/// </summary>
internal sealed class TripGrading
{
    private readonly SafeState[] _safeStates;

    public TripGrading(SafetyLimits limits, double torqueOffStageMs)
    {
        _safeStates = [.. Enum.GetValues<SafetyCheck>().Select(limits.SafeStateOf)];
        TorqueOffStageMs = torqueOffStageMs;
    }

    /// <summary>The modules' torque-off stage, ms: they switch their motors off after this much silence.</summary>
    public double TorqueOffStageMs { get; }

    /// <summary>The robot file's safe state of <paramref name="check"/>.</summary>
    public SafeState SafeStateOf(SafetyCheck check) => _safeStates[(int)check];

    /// <summary>The action of a trip of <paramref name="check"/> that measured <paramref name="measured"/>, the limit it is reported against, and whether it is soft.</summary>
    public (SafeState Action, double Limit, bool Soft) Grade(SafetyCheck check, double measured, double limit)
    {
        var action = _safeStates[(int)check];
        var silence = check.IsSilence();
        if (silence && measured >= TorqueOffStageMs)
        {
            return (SafeState.TorqueOff, TorqueOffStageMs, false);
        }

        return (action, limit, action == SafeState.Hold && (silence || check is SafetyCheck.MasterTimeout or SafetyCheck.MasterJump));
    }
}
