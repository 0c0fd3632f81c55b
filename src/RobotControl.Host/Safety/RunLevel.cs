using RobotControl.Robot.Control.States;

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

/// <summary>The run levels' names as reports and the console write them, and the moves between the levels.</summary>
public static class RunLevels
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

    /// <summary>
    /// A machine at <see cref="RunLevel.Init"/>, timing its moves on <paramref name="time"/>, every level declared once
    /// with the levels that may follow it. There is no automatic recovery: the only way out of
    /// <see cref="RunLevel.EStop"/> is an operator reset to <see cref="RunLevel.Init"/>.
    /// </summary>
    internal static StateMachine<RunLevel> NewMachine(TimeProvider time)
    {
        var levels = new StateMachine<RunLevel>("the run level", time, RunLevel.Init, Name);
        levels.Declare(RunLevel.EStop, null, RunLevel.Init);
        levels.Declare(RunLevel.Init, null, RunLevel.Homing, RunLevel.EStop);
        levels.Declare(RunLevel.Homing, null, RunLevel.PedalUp, RunLevel.Init, RunLevel.EStop);
        levels.Declare(RunLevel.PedalUp, null, RunLevel.PedalDown, RunLevel.Init, RunLevel.EStop);
        levels.Declare(RunLevel.PedalDown, null, RunLevel.PedalUp, RunLevel.EStop);
        return levels;
    }
}
