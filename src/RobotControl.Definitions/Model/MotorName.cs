namespace RobotControl.Definitions.Model;

/// <summary>
/// How a robot names its motors: <c>arm.motor</c> (e.g. <c>right.elbow</c>), unique in the robot, a motor being named
/// after the joint its axis is listed against, or after the axis for the tool's open/close drive. The robot file's
/// <c>safety.motors</c>, the modules' model, the report and fault injection all use these names.
/// </summary>
public static class MotorName
{
    /// <summary>The motor's name within its arm: the joint <paramref name="actuator"/> is listed against, or the axis name.</summary>
    public static string Of(ActuatorDefinition actuator, IReadOnlyList<JointDefinition> joints)
    {
        ArgumentNullException.ThrowIfNull(actuator);
        ArgumentNullException.ThrowIfNull(joints);
        return actuator.IsKinematic ? joints[actuator.JointIndex].Name : actuator.Name;
    }

    /// <summary>The motor's name in the robot: <c>arm.motor</c>.</summary>
    public static string Full(string arm, string motor) => $"{arm}.{motor}";
}
