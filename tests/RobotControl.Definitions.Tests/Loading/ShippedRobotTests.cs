using RobotControl.Definitions.Loading;

namespace RobotControl.Definitions.Tests.Loading;

public sealed class ShippedRobotTests
{
    private const double Deg = Math.PI / 180;

    [Fact]
    public void Crb_loads_with_the_design_values()
    {
        var robot = RobotLoader.Load(RobotFiles.Shipped("crb-1.0.json"));
        Assert.Equal("CRB-1.0", robot.Name);
        Assert.Equal(Path.GetFullPath(RobotFiles.Shipped("crb-1.0.json")), robot.SourceFile);
        Assert.Equal(4, robot.JointCount);
        Assert.Equal(5, robot.Dh.Count);
        Assert.True(robot.Dh[0].IsFixed);
        Assert.Equal(68.58, robot.Dh[2].AMm); // L1
        Assert.Equal(96.393, robot.Dh[4].DMm); // L2
        Assert.Equal(-90 * Deg, robot.Dh[2].AlphaRad, 15);
        Assert.Equal(90 * Deg, robot.Dh[3].ThetaOffsetRad, 15);
        Assert.Equal(2, robot.Dh[3].JointIndex);
        Assert.Equal(["shoulder_yaw", "shoulder_pitch", "elbow", "tool_roll"], robot.Joints.Select(j => j.Name));
        Assert.Equal(-90 * Deg, robot.Joints[0].MinRad, 15);
        Assert.Equal(45 * Deg, robot.Joints[1].MaxRad, 15);
        Assert.Equal(0, robot.Joints[2].MinRad);
        Assert.Equal(105 * Deg, robot.Joints[2].MaxRad, 15);
        Assert.Equal([0, 1, 2], robot.PositionJoints);
        Assert.Equal(8.75, robot.ShoulderCrossSectionCm2);

        // Differential shoulder: upper sun gear = phi1 + phi2, lower = phi1 - phi2.
        Assert.Equal([1.0, 1, 0, 0], robot.Actuators[0].Coupling);
        Assert.Equal([1.0, -1, 0, 0], robot.Actuators[1].Coupling);
        Assert.Equal([0.0, 0, 1, 0], robot.Actuators[2].Coupling);

        var shoulder = robot.Actuators[0].Drivetrain;
        Assert.Equal(2, shoulder.MeshesAfterGearhead);
        Assert.Equal(30.0 / 12.0, shoulder.StageRatio);
        Assert.Equal(256, shoulder.GearheadRatio);
        Assert.Equal(0.60, shoulder.GearheadEfficiency, 15);
        Assert.Equal("1226 S 012 B", shoulder.MotorModel);
        Assert.Equal(0.95 * 0.95 * 0.60, shoulder.TotalEfficiency, 15);
        var elbow = robot.Actuators[2].Drivetrain;
        Assert.Equal(16.0 / 10.0 * 1024, elbow.TotalRatio);
        Assert.Equal("0620 K 012 B", elbow.MotorModel);

        var tool = robot.Actuators[4];
        Assert.False(tool.IsKinematic);
        Assert.Equal("tool_open_close", tool.Name);
        Assert.All(tool.Coupling, c => Assert.Equal(0, c));
        Assert.Equal(18.0 / 10.0, tool.Drivetrain.StageRatio);
        Assert.Equal(0.70, tool.Drivetrain.GearheadEfficiency, 15);

        Assert.Equal(8.99, robot.Motor("1226 S 012 B").StallTorqueMNm);
        Assert.Equal(37300, robot.Motor("0620 K 012 B").NoLoadSpeedRpm);
        Assert.Equal(0.55, robot.Gearhead("06/1").Stages.Single(s => s.Ratio == 1024).Efficiency, 15);
        Assert.Equal(2.23, robot.Tool.LeadScrewMeanDiameterMm);
        Assert.Null(robot.Tool.L1Mm);
        Assert.Equal(1.0, robot.MirrorPlaneNormal.Y);
        Assert.Equal(new[] { "right", "left" }, robot.Arms.Select(a => a.Name));
        Assert.True(robot.Arms[1].Mirrored);
        Assert.Equal(2.2, robot.Requirements.ForceN.Z);
    }

    [Fact]
    public void Lb_loads_with_the_design_values()
    {
        var robot = RobotLoader.Load(RobotFiles.Shipped("lb-1.0.json"));
        Assert.Equal("LB-1.0", robot.Name);
        Assert.Equal(5, robot.JointCount);
        Assert.Equal(6, robot.Dh.Count);
        Assert.Equal(87.57, robot.Dh[3].DMm); // L1
        Assert.Equal(86.59, robot.Dh[5].DMm); // L2
        Assert.Equal(180 * Deg, robot.Dh[4].ThetaOffsetRad, 15);
        Assert.Equal(0, robot.Joints[3].MinRad);
        Assert.Equal(150 * Deg, robot.Joints[3].MaxRad, 15);
        Assert.Equal(-90 * Deg, robot.Joints[0].MinRad, 15);
        Assert.All(robot.Joints, j => Assert.False(string.IsNullOrWhiteSpace(j.RangeSource)));

        // Three concentric shafts: upper = phi1 + phi2, lower = phi1 - phi2, middle = phi3 - phi1 - phi2.
        Assert.Equal([1.0, 1, 0, 0, 0], robot.Actuators[0].Coupling);
        Assert.Equal([1.0, -1, 0, 0, 0], robot.Actuators[1].Coupling);
        Assert.Equal([-1.0, -1, 1, 0, 0], robot.Actuators[2].Coupling);

        var shoulder3 = robot.Actuators[2].Drivetrain;
        Assert.Equal(4, shoulder3.MeshesAfterGearhead);
        Assert.Equal(30.0 / 14.0, shoulder3.StageRatio);
        Assert.Equal(18.0 / 12.0, robot.Actuators[3].Drivetrain.StageRatio);
        Assert.Equal(1024, robot.Actuators[3].Drivetrain.GearheadRatio);
        Assert.Equal(24.0 / 12.0, robot.Actuators[5].Drivetrain.StageRatio);
        Assert.Equal(4.13, robot.ShoulderCrossSectionCm2);
        Assert.Equal(150 * Deg, robot.CrossSection.YMaxRad, 15);
        Assert.Equal(robot.IndexOfJoint("elbow"), robot.CrossSection.YJoint);
    }
}
