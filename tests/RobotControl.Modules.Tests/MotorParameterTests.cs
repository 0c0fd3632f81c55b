using RobotControl.Bus.Protocol;
using RobotControl.TestSupport;

namespace RobotControl.Modules.Tests;

/// <summary>The units table: the robot file's values in the module's counts, and the console's edits both ways.</summary>
public sealed class MotorParameterTests
{
    private static readonly MotorConfig Shoulder = Config(1, 0);

    [Theory]
    [InlineData("gear_ratio", 548571, "548.571:1")]
    [InlineData("kp", 2492, "20 duty/rad")]
    [InlineData("current_limit", 1147, "0.7 A")]
    [InlineData("speed_limit", 1097, "120.0 deg/s")]
    public void The_robot_file_s_value_is_the_same_in_the_units_table_and_the_module_parameters(string key, long counts, string text)
    {
        var p = MotorParameter.Find(key)!;
        var value = Assert.Single(ModuleParameters.For(ShippedRobots.Lb, Shoulder.Module, ControlTable.Firmware), v => v.Field.Name == key && v.Motor == 0);

        Assert.Equal(counts, p.FileCounts(Shoulder));
        Assert.Equal((counts, text), (value.Value, value.Meaning));
    }

    [Theory]
    [InlineData("gear_ratio", 548.571, 548571)]
    [InlineData("kp", 20, 2492)]
    [InlineData("current_limit", 0.7, 1147)]
    [InlineData("speed_limit", 120, 1097)]
    public void A_value_in_robot_units_becomes_the_module_s_counts_and_back(string key, double value, long counts)
    {
        var p = MotorParameter.Find(key)!;

        Assert.Equal(counts, p.ToCounts(Shoulder, value, out var problem));
        Assert.Empty(problem);
        Assert.Equal(value, p.FromCounts(Shoulder, counts), 0.5 / p.ToCounts(Shoulder, 1, out _)!.Value + 1e-9);
    }

    [Theory]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(1e300)]
    public void A_value_no_field_can_hold_is_refused_by_name(double value)
    {
        Assert.Null(MotorParameter.Find("kp")!.ToCounts(Shoulder, value, out var problem));
        Assert.StartsWith("kp = ", problem, StringComparison.Ordinal);
        Assert.EndsWith("is no value kp can hold (give a finite number)", problem, StringComparison.Ordinal);
    }

    [Fact]
    public void The_range_in_robot_units_is_what_the_rules_accept()
    {
        var p = MotorParameter.Find("current_limit")!;
        var (min, max) = p.Range(Shoulder);

        Assert.Equal(0, min);
        Assert.Equal(4095 / Shoulder.RawPerAmp, max, 1e-12);
        Assert.Null(ParameterRules.CheckValue(p.Field, p.ToCounts(Shoulder, max, out _)!.Value));
        Assert.NotNull(ParameterRules.CheckValue(p.Field, p.ToCounts(Shoulder, max + (1 / Shoulder.RawPerAmp), out _)!.Value));
    }

    private static MotorConfig Config(byte id, int channel)
    {
        var robot = ShippedRobots.Lb;
        var module = robot.Modules.Modules.Single(m => m.Id == id);
        return new MotorConfig(robot, module, module.Motors.Single(m => m.Channel == channel));
    }
}
