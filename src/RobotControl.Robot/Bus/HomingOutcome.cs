namespace RobotControl.Robot.Bus;

/// <summary>How homing one motor from its pot ended (<see cref="BusRobot.Home"/>).</summary>
public enum HomingOutcome
{
    /// <summary>The module took the position from the pot, and the position read back agrees with the pot.</summary>
    Homed,

    /// <summary>The motor has no pot calibration (fewer than 2 points): not homed, its position is what it was.</summary>
    NotCalibrated,

    /// <summary>The module refused the home request (a motor of it is driven or uncalibrated): nothing changed.</summary>
    Refused,

    /// <summary>The module accepted, but the position read back disagrees with the pot or an error bit is still set.</summary>
    VerifyFailed,

    /// <summary>The module did not answer.</summary>
    NoReply,
}
