namespace RobotControl.Analysis.CurrentLimits;

/// <summary>
/// Motor currents at which an actuator's gearhead reaches its output-torque ratings, and the joint speed its maximum
/// input speed allows.
/// </summary>
/// <param name="Actuator">Actuator name.</param>
/// <param name="Joint">Joint it is listed against, or null (tool open/close).</param>
/// <param name="GearheadSeries">Gearhead series.</param>
/// <param name="ContinuousCurrentA">Current at the continuous output-torque rating, A (no-load current included).</param>
/// <param name="IntermittentCurrentA">Current at the intermittent output-torque rating, A (no-load current included).</param>
/// <param name="StallCurrentA">Stall current U/R; the motor cannot draw more at nominal voltage, A.</param>
/// <param name="StallTorqueAtGearheadMNm">The motor's stall torque through the gearhead (T_stall·tau_m·eta_m), mNm.</param>
/// <param name="ContinuousRatingMNm">The gearhead's continuous output-torque rating, mNm.</param>
/// <param name="IntermittentRatingMNm">The gearhead's intermittent output-torque rating, mNm.</param>
/// <param name="MaxInputSpeedRpm">The gearhead's maximum (continuous) input speed, rpm.</param>
/// <param name="MotorNoLoadSpeedRpm">The motor's no-load speed, rpm.</param>
/// <param name="JointSpeedLimitRpm">Output speed at the gearhead's maximum input speed when that is below the motor's no-load speed, else null.</param>
public sealed record CurrentLimit(
    string Actuator,
    string? Joint,
    string GearheadSeries,
    double ContinuousCurrentA,
    double IntermittentCurrentA,
    double StallCurrentA,
    double StallTorqueAtGearheadMNm,
    double ContinuousRatingMNm,
    double IntermittentRatingMNm,
    double MaxInputSpeedRpm,
    double MotorNoLoadSpeedRpm,
    double? JointSpeedLimitRpm)
{
    /// <summary>True when the motor at stall could exceed the continuous rating, i.e. the current limit is needed.</summary>
    public bool StallExceedsContinuousRating => StallTorqueAtGearheadMNm > ContinuousRatingMNm;
}
