using RobotControl.Analysis.CurrentLimits;

namespace RobotControl.Analysis.Tests.CurrentLimits;

public sealed class CurrentLimitCalculatorTests
{
    [Fact]
    public void Crb_shoulder_limits_follow_from_the_gearhead_rating_and_torque_constant()
    {
        var shoulder = CurrentLimitCalculator.EvaluateAll(TestRobots.Crb)[0];

        // I = T_rating / (k_t · tau_m · eta_m) + I_0 for the 1226 S 012 B (4.12 mNm/A, 0.054 A) on a 256:1, 60 % gearhead.
        Assert.Equal((300 / (4.12 * 256 * 0.60)) + 0.054, shoulder.ContinuousCurrentA, 9);
        Assert.Equal((450 / (4.12 * 256 * 0.60)) + 0.054, shoulder.IntermittentCurrentA, 9);
        Assert.True(shoulder.StallExceedsContinuousRating);
        Assert.True(shoulder.ContinuousCurrentA < shoulder.StallCurrentA);
    }

    [Fact]
    public void Joint_speed_limit_comes_from_the_gearhead_input_speed_when_lower_than_the_motors()
    {
        var limits = CurrentLimitCalculator.EvaluateAll(TestRobots.Lb);
        var shoulder = limits[0];
        var elbow = limits.Single(l => l.Joint == "elbow");

        Assert.Equal(5000 / ((30.0 / 14) * 256), shoulder.JointSpeedLimitRpm!.Value, 9);
        Assert.Equal(8000 / ((18.0 / 12) * 1024), elbow.JointSpeedLimitRpm!.Value, 9);
    }
}
