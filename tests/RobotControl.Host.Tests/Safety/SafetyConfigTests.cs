using System.Text.Json;
using RobotControl.Host.Harness;
using RobotControl.Host.Safety;

namespace RobotControl.Host.Tests.Safety;

public sealed class SafetyConfigTests
{
    [Fact]
    public void A_robot_file_without_a_safety_section_gets_the_defaults()
    {
        var robot = Path.Combine(Path.GetDirectoryName(Path.GetDirectoryName(Graphs.Path("teleop-lb.json")))!, "hardware", "robots", "lb-1.0.json");
        var limits = SafetySection.Load(robot);
        Assert.Equal(new SafetyLimits().TrackingErrorRad, limits.TrackingErrorRad);
        Assert.Equal(SafeState.TorqueOff, limits.SafeStateOf(SafetyCheck.OverCurrent));
        Assert.Equal(SafeState.Hold, limits.SafeStateOf(SafetyCheck.TrackingError));
    }

    [Fact]
    public void The_section_sets_thresholds_and_safe_states_and_names_a_bad_field()
    {
        using var doc = JsonDocument.Parse("""{ "tracking_error_rad": 0.1, "over_current_ms": 20, "safe_state": { "tracking_error": "torque_off" } }""");
        var limits = SafetySection.Parse(doc.RootElement, "r.json");
        Assert.Equal(0.1, limits.TrackingErrorRad);
        Assert.Equal(20, limits.OverCurrentMs);
        Assert.Equal(SafeState.TorqueOff, limits.SafeStateOf(SafetyCheck.TrackingError));

        using var bad = JsonDocument.Parse("""{ "over_current_ms": -1 }""");
        var error = Assert.Throws<FormatException>(() => SafetySection.Parse(bad.RootElement, "r.json"));
        Assert.Equal("r.json: safety.over_current_ms: expected a number from 0 to 10000, got -1", error.Message);
        using var unknown = JsonDocument.Parse("""{ "safe_state": { "tracking_error": "brake" } }""");
        Assert.Contains("safety.safe_state.tracking_error", Assert.Throws<FormatException>(() => SafetySection.Parse(unknown.RootElement, "r.json")).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Thresholds_per_motor_override_the_robot_wide_ones_and_an_unknown_motor_is_refused_in_one_line()
    {
        using var doc = JsonDocument.Parse("""{ "pot_distance_rad": 0.1, "motors": { "right.elbow": { "tracking_error_rad": 0.2 }, "left.elbow": { "pot_distance_rad": 0.3 } } }""");
        var limits = SafetySection.Parse(doc.RootElement, "r.json", ["right.elbow", "left.elbow"]);
        Assert.Equal(0.2, limits.TrackingErrorRadOf("right.elbow"));
        Assert.Equal(0.1, limits.PotDistanceRadOf("right.elbow"));
        Assert.Equal(0.3, limits.PotDistanceRadOf("left.elbow"));
        Assert.Equal(new SafetyLimits().TrackingErrorRad, limits.TrackingErrorRadOf("left.elbow"));
        Assert.Equal(5 * Math.PI / 180, new SafetyLimits().PotDistanceRadOf("right.elbow"));

        using var unknown = JsonDocument.Parse("""{ "motors": { "right.knee": { "tracking_error_rad": 0.2 } } }""");
        Assert.Equal("r.json: safety.motors.right.knee: no such motor (known: right.elbow)", Assert.Throws<FormatException>(() => SafetySection.Parse(unknown.RootElement, "r.json", ["right.elbow"])).Message);
        using var bad = JsonDocument.Parse("""{ "motors": { "right.elbow": { "pot_distance_rad": 0 } } }""");
        Assert.Equal("r.json: safety.motors.right.elbow.pot_distance_rad: expected a number from 1E-06 to 6.283185307179586, got 0", Assert.Throws<FormatException>(() => SafetySection.Parse(bad.RootElement, "r.json", ["right.elbow"])).Message);
        using var field = JsonDocument.Parse("""{ "motors": { "right.elbow": { "current_limit_fraction": 1 } } }""");
        Assert.Contains("safety.motors.right.elbow.current_limit_fraction: unknown field", Assert.Throws<FormatException>(() => SafetySection.Parse(field.RootElement, "r.json", ["right.elbow"])).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Inject_parses_the_safety_faults_and_keeps_ber_and_reset()
    {
        var f = FaultInjection.Parse("ber=1e-5,reset=right.shoulder@5s,stall=100ms@5s,stuck=right.elbow@5s,current=right.elbow@2.5s,nan=ik_right@5s,pot=right.elbow@5s");
        Assert.Equal(1e-5, f.BitErrorRate);
        Assert.Single(f.Resets);
        Assert.Equal([TimedFaultKind.Stall, TimedFaultKind.Stuck, TimedFaultKind.Current, TimedFaultKind.Nan, TimedFaultKind.Pot], f.TimedFaults.Select(t => t.Kind));
        Assert.Equal(TimeSpan.FromMilliseconds(100), f.TimedFaults[0].Duration);
        Assert.Equal(TimeSpan.FromSeconds(2.5), f.TimedFaults[2].At);
        Assert.Equal("ber=1E-05,reset=right.shoulder@5s,stall=100ms@5s,stuck=right.elbow@5s,current=right.elbow@2.5s,nan=ik_right@5s,pot=right.elbow@5s", f.ToString());
        Assert.Contains("expected stuck=<arm.motor>@<time>", Assert.Throws<FormatException>(() => FaultInjection.Parse("stuck=right.elbow")).Message, StringComparison.Ordinal);
        Assert.Contains("unknown fault", Assert.Throws<FormatException>(() => FaultInjection.Parse("melt=right.elbow@1s")).Message, StringComparison.Ordinal);
    }

    [Fact]
    public void The_bus_watchdog_must_be_on_and_no_longer_than_its_safety_limit()
    {
        var limits = new SafetyLimits();
        Assert.Equal(30, limits.BusWatchdogMaxMs);
        SafetySection.CheckWatchdog(limits, 30, "r.json");
        Assert.Equal(
            "r.json: modules.watchdog_ms: 0 switches the modules' bus watchdogs off; the safety supervisor needs 1 to 30 ms (safety.bus_watchdog_max_ms)",
            Assert.Throws<FormatException>(() => SafetySection.CheckWatchdog(limits, 0, "r.json")).Message);
        Assert.Equal(
            "r.json: modules.watchdog_ms: 100 ms is longer than safety.bus_watchdog_max_ms (30 ms): a module would drive on for 100 ms after the host stops",
            Assert.Throws<FormatException>(() => SafetySection.CheckWatchdog(limits, 100, "r.json")).Message);
        using var relaxed = System.Text.Json.JsonDocument.Parse("{ \"bus_watchdog_max_ms\": 100 }");
        SafetySection.CheckWatchdog(SafetySection.Parse(relaxed.RootElement, "r.json"), 100, "r.json");
        using var bad = System.Text.Json.JsonDocument.Parse("{ \"bus_watchdog_max_ms\": 0 }");
        Assert.Equal("r.json: safety.bus_watchdog_max_ms: expected a number from 1 to 60000, got 0", Assert.Throws<FormatException>(() => SafetySection.Parse(bad.RootElement, "r.json")).Message);
    }
}
