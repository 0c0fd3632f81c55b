using RobotControl.Definitions.Json;
using RobotControl.Plugins.Standard.Kinematics;

namespace RobotControl.Plugins.Standard.Tests.Kinematics;

/// <summary>The IK's <c>initial_joints_deg</c>: comma-separated degrees, checked before any instance is made.</summary>
public sealed class InverseKinematicsSettingsTests
{
    [Theory]
    [InlineData("")]
    [InlineData("  ")]
    [InlineData("-30, -30,0 ,90,0")]
    [InlineData("1e1,-0.5")]
    public void Empty_or_comma_separated_numbers_are_consistent(string text)
    {
        Assert.Empty(new InverseKinematicsSettings { InitialJointsDeg = text }.CheckConsistency());
    }

    [Theory]
    [InlineData("-30,x,0", "x")]
    [InlineData("-30,,0", "")]
    [InlineData("10,NaN,Infinity", "NaN")]
    [InlineData("90 deg", "90 deg")]
    public void The_first_part_that_is_not_a_finite_number_is_named_once(string text, string part)
    {
        var problem = Assert.Single(new InverseKinematicsSettings { InitialJointsDeg = text }.CheckConsistency());
        Assert.Equal(new JsonProblem("initial_joints_deg", $"'{part}' is not a number (expected comma-separated degrees)"), problem);
    }
}
