using RobotControl.Definitions.Model;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

/// <summary>A trip in one line, as the run-level reasons and the console show it.</summary>
public sealed class SafetyTripTests
{
    [Fact]
    public void A_trip_names_its_check_what_it_concerns_the_value_against_its_limit_and_the_safe_state()
    {
        Assert.Equal("module_silent left.forearm: 52.346 ms (limit 50 ms): torque_off", new SafetyTrip(0, SafetyCheck.ModuleSilent, "left.forearm", 52.3456, 50, "ms", SafeState.TorqueOff).ToString());
        Assert.Equal("host_stall: 23.1 ms (limit 10 ms): hold, back to PEDAL_UP", new SafetyTrip(0, SafetyCheck.HostStall, string.Empty, 23.1, 10, "ms", SafeState.Hold, Soft: true).ToString());
        Assert.Equal("operator: hold", new SafetyTrip(0, SafetyCheck.Operator, string.Empty, 0, 0, string.Empty, SafeState.Hold).ToString()); // no value without a unit
        Assert.Equal("non_finite setpoint: NaN rad (limit 0 rad): hold", new SafetyTrip(0, SafetyCheck.NonFinite, "setpoint", double.NaN, 0, "rad", SafeState.Hold).ToString());
    }
}
