using RobotControl.Definitions.Model;

namespace RobotControl.Analysis.Drivetrain;

/// <summary>
/// The reference design's per-joint limits: joint i may run at the output speed and hold the output torque of the
/// actuator listed against it, independently of every other joint (differential couplings ignored).
/// </summary>
internal sealed class JointDriveLimits
{
    private JointDriveLimits(double[] speedRadPerS, double[] torqueMNm)
    {
        SpeedRadPerS = speedRadPerS;
        TorqueMNm = torqueMNm;
    }

    /// <summary>Maximum speed per joint (joint-vector order), rad/s; NaN for a joint no actuator is listed against.</summary>
    public double[] SpeedRadPerS { get; }

    /// <summary>Holding torque per joint (joint-vector order), mNm; NaN for a joint no actuator is listed against.</summary>
    public double[] TorqueMNm { get; }

    public static JointDriveLimits FromRobot(RobotDefinition robot, IReadOnlyList<DrivetrainPerformance> performance)
    {
        var speed = new double[robot.JointCount];
        var torque = new double[robot.JointCount];
        Array.Fill(speed, double.NaN);
        Array.Fill(torque, double.NaN);
        for (var k = 0; k < robot.Actuators.Count; k++)
        {
            var joint = robot.Actuators[k].JointIndex;
            if (joint >= 0)
            {
                speed[joint] = performance[k].SpeedRadPerS;
                torque[joint] = performance[k].TorqueMNm;
            }
        }

        return new JointDriveLimits(speed, torque);
    }

    /// <summary>Throws when a joint the analysis uses has no actuator listed against it.</summary>
    public void RequireJoints(RobotDefinition robot, IReadOnlyList<int> joints)
    {
        foreach (var j in joints)
        {
            if (double.IsNaN(SpeedRadPerS[j]))
            {
                throw new ArgumentException($"{robot.Name}: joint '{robot.Joints[j].Name}' is used by the analysis but no actuator is listed against it");
            }
        }
    }
}
