using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Drivetrain;

/// <summary>
/// The design's drivetrain formula (docs/robots.md, drivetrains): T_joint = eta^n · tau · eta_m · tau_m · T_stall and
/// omega_joint = omega_noload / (tau · tau_m).
/// </summary>
public static class DrivetrainCalculator
{
    /// <summary>Torque and speed at the output of one actuator's drivetrain.</summary>
    public static DrivetrainPerformance Evaluate(RobotDefinition robot, ActuatorDefinition actuator)
    {
        ArgumentNullException.ThrowIfNull(robot);
        ArgumentNullException.ThrowIfNull(actuator);
        var drivetrain = actuator.Drivetrain;
        var motor = robot.Motor(drivetrain.MotorModel);
        var torque = drivetrain.TotalEfficiency * drivetrain.TotalRatio * motor.StallTorqueMNm;
        var speed = motor.NoLoadSpeedRpm / drivetrain.TotalRatio;
        var joint = actuator.IsKinematic ? robot.Joints[actuator.JointIndex].Name : null;
        return new DrivetrainPerformance(actuator.Name, joint, torque, speed);
    }

    /// <summary>Every actuator of the robot in file order, the tool's open/close drive included.</summary>
    public static IReadOnlyList<DrivetrainPerformance> EvaluateAll(RobotDefinition robot)
    {
        ArgumentNullException.ThrowIfNull(robot);
        return robot.Actuators.Select(a => Evaluate(robot, a)).ToArray();
    }
}
