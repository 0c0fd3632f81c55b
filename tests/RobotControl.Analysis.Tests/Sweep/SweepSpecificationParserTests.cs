using RobotControl.Analysis.Sweep;

namespace RobotControl.Analysis.Tests.Sweep;

public sealed class SweepSpecificationParserTests
{
    [Fact]
    public void The_reference_cross_section_written_out_parses_to_the_files_grid()
    {
        var robot = TestRobots.Lb;
        var parsed = SweepSpecificationParser.Parse("shoulder_yaw:-90:45,elbow:0:150,step=1,fixed=shoulder_pitch:0,shoulder_roll:0", robot);
        var reference = SweepSpecification.FromCrossSection(robot.CrossSection);

        Assert.Equal(reference.XJoint, parsed.XJoint);
        Assert.Equal(reference.YJoint, parsed.YJoint);
        Assert.Equal(reference.XCount, parsed.XCount);
        Assert.Equal(reference.YCount, parsed.YCount);
        Assert.Equal(reference.JointsUsed, parsed.JointsUsed);
        Assert.Equal(136, parsed.XCount);
        Assert.Equal(151, parsed.YCount);
    }

    [Fact]
    public void Symbols_steps_and_fixed_values_are_read()
    {
        var robot = TestRobots.Crb;
        var spec = SweepSpecificationParser.Parse("phi2:-90:45, phi3:0:105, step=5, fixed=phi1:-30", robot);

        Assert.Equal(1, spec.XJoint);
        Assert.Equal(2, spec.YJoint);
        Assert.Equal(28, spec.XCount);
        Assert.Equal(22, spec.YCount);
        Assert.Equal(-30 * Math.PI / 180, spec.FixedRad[0], 12);
    }

    [Theory]
    [InlineData("shoulder_yaw:-90:45", "expected")]
    [InlineData("wrist:-90:45,elbow:0:105", "unknown joint 'wrist'")]
    [InlineData("shoulder_yaw:-120:45,elbow:0:105", "within its range")]
    [InlineData("shoulder_yaw:-90:45,elbow:0:105,step=0", "positive")]
    [InlineData("shoulder_yaw:-90:45,elbow:0:105,speed=3", "unknown key")]
    [InlineData("shoulder_yaw:a:45,elbow:0:105", "not a number")]
    [InlineData("elbow:0:45,elbow:0:105", "must differ")]
    public void Malformed_text_is_rejected_with_a_message_naming_the_problem(string text, string expected)
    {
        var ex = Assert.Throws<FormatException>(() => SweepSpecificationParser.Parse(text, TestRobots.Crb));

        Assert.Contains(expected, ex.Message, StringComparison.Ordinal);
    }
}
