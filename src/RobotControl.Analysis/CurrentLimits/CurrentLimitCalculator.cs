using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.CurrentLimits;

/// <summary>
/// Current limits that keep a gearhead within its output-torque ratings. The gearhead output torque is
/// T_out = T_motor · tau_m · eta_m, and the motor's shaft torque is T_motor = k_t · (I − I_0): the no-load current
/// I_0 is what the motor draws to overcome its own friction (Faulhaber's datasheet convention), so it produces no
/// output torque. Hence I = T_rating / (k_t · tau_m · eta_m) + I_0. The spur/bevel stages after the gearhead do not
/// enter: the ratings are for the gearhead's own output shaft. The speed limit is the gearhead's maximum input speed
/// divided by the total reduction tau · tau_m, reported only where it is below the motor's no-load speed.
/// </summary>
public static class CurrentLimitCalculator
{
    /// <summary>Limits for one actuator.</summary>
    public static CurrentLimit Evaluate(RobotDefinition robot, ActuatorDefinition actuator)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(actuator);
        var drivetrain = actuator.Drivetrain;
        var motor = robot.Motor(drivetrain.MotorModel);
        var gearhead = robot.Gearhead(drivetrain.GearheadSeries);
        var torquePerAmp = motor.TorqueConstantMNmPerA * drivetrain.GearheadRatio * drivetrain.GearheadEfficiency;
        var stallCurrent = motor.NominalVoltageV / motor.TerminalResistanceOhm;
        double? speedLimit = gearhead.MaxInputSpeedRpm < motor.NoLoadSpeedRpm
            ? gearhead.MaxInputSpeedRpm / drivetrain.TotalRatio
            : null;
        return new CurrentLimit(
            actuator.Name,
            actuator.IsKinematic ? robot.Joints[actuator.JointIndex].Name : null,
            gearhead.Series,
            (gearhead.ContinuousOutputTorqueMNm / torquePerAmp) + motor.NoLoadCurrentA,
            (gearhead.IntermittentOutputTorqueMNm / torquePerAmp) + motor.NoLoadCurrentA,
            stallCurrent,
            motor.StallTorqueMNm * drivetrain.GearheadRatio * drivetrain.GearheadEfficiency,
            gearhead.ContinuousOutputTorqueMNm,
            gearhead.IntermittentOutputTorqueMNm,
            gearhead.MaxInputSpeedRpm,
            motor.NoLoadSpeedRpm,
            speedLimit);
    }

    /// <summary>Limits for every actuator in file order.</summary>
    public static IReadOnlyList<CurrentLimit> EvaluateAll(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        return robot.Actuators.Select(a => Evaluate(robot, a)).ToArray();
    }
}
