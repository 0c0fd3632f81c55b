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

    [Theory]
    [InlineData("current_limit", "current_limit = 0 switches the motor's current limit off")]
    [InlineData("speed_limit", "speed_limit = 0 switches the motor's setpoint speed limit off")]
    [InlineData("bus_watchdog", "bus_watchdog = 0 switches the module's bus watchdog (both stages) off")]
    public void Zero_in_a_protection_field_is_refused_unless_allowed_and_says_what_goes_off(string field, string off)
    {
        Assert.Equal(off, ParameterRules.ProtectionOff(Table[field], 0));
        Assert.Equal($"{off}; a protection goes off only on purpose (robotctl params set --allow-protection-off)", ParameterRules.CheckValue(Table[field], 0));
        Assert.Null(ParameterRules.CheckValue(Table[field], 0, allowProtectionOff: true));
        Assert.Null(ParameterRules.ProtectionOff(Table[field], 1));
        Assert.Null(ParameterRules.CheckValue(Table[field], 1));
    }

    [Fact]
    public void Allowing_a_protection_off_does_not_let_a_value_outside_the_range_through() =>
        Assert.StartsWith("current_limit = 4096 is outside its range", ParameterRules.CheckValue(Table["current_limit"], 4096, allowProtectionOff: true), StringComparison.Ordinal);

    /// <summary>
    /// The protections are the control table's: every field whose description says that 0 switches it off (disables,
    /// "= off", "= unlimited") is marked <c>zero_disables</c>, and no other, so a new such field cannot be forgotten.
    /// </summary>
    [Fact]
    public void Every_field_whose_zero_switches_something_off_is_marked_in_the_control_table()
    {
        string[] phrases = ["0 disables", "0 = off", "0 = unlimited"];
        var described = Table.Fields.Where(f => phrases.Any(p => f.Description.Contains(p, StringComparison.Ordinal))).Select(f => f.Name).Order();
        var marked = Table.Fields.Where(f => f.ZeroDisables is not null).Select(f => f.Name).Order();

        Assert.Equal(["bus_watchdog", "current_limit", "speed_limit"], marked);
        Assert.Equal(described, marked);
    }

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
