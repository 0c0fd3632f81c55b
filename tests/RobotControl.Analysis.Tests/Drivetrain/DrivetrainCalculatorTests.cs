using RobotControl.Analysis.Drivetrain;

namespace RobotControl.Analysis.Tests.Drivetrain;

public sealed class DrivetrainCalculatorTests
{
    [Fact]
    public void Lb_shoulder_matches_the_hand_computed_formula()
    {
        var shoulder = DrivetrainCalculator.EvaluateAll(TestRobots.Lb)[0];

        Assert.Equal("shoulder_yaw", shoulder.Joint);
        Assert.Equal(0.95 * 0.95 * (30.0 / 14) * 0.60 * 256 * 8.99, shoulder.TorqueMNm, 9);
        Assert.Equal(2670.49, shoulder.TorqueMNm, 2);
        Assert.Equal(27400 / ((30.0 / 14) * 256), shoulder.SpeedRpm, 9);
    }

    [Fact]
    public void Lb_shoulder_roll_has_four_meshes()
    {
        var roll = DrivetrainCalculator.EvaluateAll(TestRobots.Lb)[2];

        Assert.Equal(Math.Pow(0.95, 4) * (30.0 / 14) * 0.60 * 256 * 8.99, roll.TorqueMNm, 9);
    }

    [Fact]
    public void Crb_elbow_and_tool_drive_match_the_hand_computed_formula()
    {
        var all = DrivetrainCalculator.EvaluateAll(TestRobots.Crb);
        var elbow = all.Single(d => d.Joint == "elbow");
        var tool = all[^1];

        Assert.Equal(0.95 * 0.95 * 1.6 * 0.55 * 1024 * 0.551, elbow.TorqueMNm, 9);
        Assert.Equal(37300 / (1.6 * 1024), elbow.SpeedRpm, 9);
        Assert.Equal("tool_open_close", tool.Actuator);
        Assert.Null(tool.Joint);
        Assert.Equal(0.95 * 1.8 * 0.70 * 256 * 0.551, tool.TorqueMNm, 9);
        Assert.Equal(37300 / (1.8 * 256), tool.SpeedRpm, 9);
    }

    [Fact]
    public void Every_actuator_is_listed_in_file_order()
    {
        Assert.Equal(
            ["shoulder_1", "shoulder_2", "elbow", "tool_roll", "tool_open_close"],
            DrivetrainCalculator.EvaluateAll(TestRobots.Crb).Select(d => d.Actuator));
        Assert.Equal(6, DrivetrainCalculator.EvaluateAll(TestRobots.Lb).Count);
    }

    [Fact]
    public void Speed_in_rad_per_s_converts_rpm()
    {
        var d = new DrivetrainPerformance("a", "j", 1, 60);

        Assert.Equal(2 * Math.PI, d.SpeedRadPerS, 12);
    }
}
