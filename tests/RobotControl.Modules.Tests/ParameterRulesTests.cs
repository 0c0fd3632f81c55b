using RobotControl.Bus.Protocol;
using RobotControl.Modules;

namespace RobotControl.Modules.Tests;

public sealed class ParameterRulesTests
{
    private static readonly ControlTable Table = ControlTable.Firmware;

    [Theory]
    [InlineData("current_limit", 65536L)]
    [InlineData("control_mode", 257L)]
    [InlineData("kp", -1L)]
    [InlineData("pot_cal_count", 9L)]
    [InlineData("model_number", 1L)]
    public void A_value_the_field_cannot_hold_is_refused_before_any_cast(string field, long value) =>
        Assert.NotNull(ParameterRules.CheckValue(Table[field], value));

    [Theory]
    [InlineData("current_limit", 4095L)]
    [InlineData("kp", 0L)]
    [InlineData("position_min", int.MinValue)]
    public void A_value_inside_the_field_is_accepted(string field, long value) =>
        Assert.Null(ParameterRules.CheckValue(Table[field], value));

    [Fact]
    public void Cross_field_rules_hold_per_motor_and_only_for_the_changed_field()
    {
        var values = new Dictionary<string, long>
        {
            ["position_min"] = 100, ["position_max"] = 50, ["pot_cal_count"] = 3, ["pot_cal_step"] = 10,
            ["pot_cal_raw0"] = 10, ["pot_cal_raw1"] = 30, ["pot_cal_raw2"] = 20,
        };
        long Value(string name, int motor) => values.TryGetValue(name, out var v) ? v : 0;

        Assert.Equal(2, ParameterRules.CheckMotor(Value, 0).Count);
        Assert.Single(ParameterRules.CheckMotor(Value, 0, "position_max"));
        Assert.Empty(ParameterRules.CheckMotor(Value, 0, "kp"));
        values["pot_cal_raw2"] = 40;
        values["position_max"] = 101;
        Assert.Empty(ParameterRules.CheckMotor(Value, 0));
        values["pot_cal_count"] = 1;
        Assert.Contains("pot_cal_count 1", Assert.Single(ParameterRules.CheckMotor(Value, 0)), StringComparison.Ordinal);
    }
}
