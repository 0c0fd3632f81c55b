namespace RobotControl.Analysis.Drivetrain;

/// <summary>Output torque and speed of one driven axis, from its motor, gearhead and spur/bevel stages.</summary>
/// <param name="Actuator">Actuator name from the robot file, e.g. <c>shoulder_1</c>.</param>
/// <param name="Joint">The joint the actuator is listed against, or null for a drive with no kinematic joint (tool open/close).</param>
/// <param name="TorqueMNm">T = eta^n · tau · eta_m · tau_m · T_stall, mNm at the stage output.</param>
/// <param name="SpeedRpm">omega = omega_noload / (tau · tau_m), rpm at the stage output.</param>
public sealed record DrivetrainPerformance(string Actuator, string? Joint, double TorqueMNm, double SpeedRpm)
{
    /// <summary>The output speed in rad/s.</summary>
    public double SpeedRadPerS => SpeedRpm * 2.0 * Math.PI / 60.0;
}
