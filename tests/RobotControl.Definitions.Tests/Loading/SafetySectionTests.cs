using System.Text.Json.Nodes;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Tests.Loading;

/// <summary>The robot file's <c>safety</c> section and the bus watchdog's two stages it bounds, as the loader reads them.</summary>
public sealed class SafetySectionTests : IDisposable
{
    private const string LbMotors =
        "right.shoulder_yaw, right.shoulder_pitch, right.shoulder_roll, right.elbow, right.tool_roll, right.tool_open_close, "
        + "left.shoulder_yaw, left.shoulder_pitch, left.shoulder_roll, left.elbow, left.tool_roll, left.tool_open_close";

    private readonly RobotFiles _files = new();

    public void Dispose() => _files.Dispose();

    [Fact]
    public void A_robot_file_without_a_safety_section_gets_the_defaults()
    {
        var limits = RobotLoader.Load(RobotFiles.Shipped("lb-1.0.json")).Safety;
        var defaults = new SafetyLimits();
        Assert.Equal(0.35, defaults.TrackingErrorRad);
        Assert.Equal(defaults.TrackingErrorRad, limits.TrackingErrorRad);
        Assert.Equal(defaults.OverCurrentMs, limits.OverCurrentMs);
        Assert.Equal(defaults.BusWatchdogMaxMs, limits.BusWatchdogMaxMs);
        Assert.Equal(defaults.BusWatchdogOffMaxMs, limits.BusWatchdogOffMaxMs);
        Assert.Equal(defaults.DeadlineMissesInARow, limits.DeadlineMissesInARow);
        Assert.Empty(limits.Motors);
        Assert.Equal(SafeState.TorqueOff, limits.SafeStateOf(SafetyCheck.OverCurrent));
        Assert.Equal(SafeState.Hold, limits.SafeStateOf(SafetyCheck.TrackingError));
    }

    [Fact]
    public void The_section_sets_thresholds_and_safe_states_and_names_a_bad_field()
    {
        var limits = Load("""{ "tracking_error_rad": 0.1, "over_current_ms": 20, "deadline_misses_in_a_row": 4, "safe_state": { "tracking_error": "torque_off" } }""");
        Assert.Equal(0.1, limits.TrackingErrorRad);
        Assert.Equal(20, limits.OverCurrentMs);
        Assert.Equal(4, limits.DeadlineMissesInARow);
        Assert.Equal(SafeState.TorqueOff, limits.SafeStateOf(SafetyCheck.TrackingError));
        Assert.Equal(SafeState.TorqueOff, limits.SafeStateOf(SafetyCheck.OverCurrent)); // the fields not given keep their defaults
        Assert.Equal(new SafetyLimits().PotMismatchMs, limits.PotMismatchMs);

        AssertOneLine("""{ "over_current_ms": -1 }""", "$.safety.over_current_ms", "is -1; must be at least 0");
        AssertOneLine("""{ "safe_state": { "tracking_error": "brake" } }""", "$.safety.safe_state.tracking_error", "must be \"hold\" or \"torque_off\", found the string \"brake\"");
    }

    [Theory]
    [InlineData("[]", "$.safety", "must be an object, found an array")]
    [InlineData("null", "$.safety", "must be an object, not null")]
    [InlineData("""{ "tracking_error_deg": 20 }""", "$.safety.tracking_error_deg", "wrong unit: expected 'tracking_error_rad' (unit 'rad'), found unit 'deg'")]
    [InlineData("""{ "brakes": true }""", "$.safety.brakes", "unknown field")]
    [InlineData("""{ "tracking_error_rad": 4 }""", "$.safety.tracking_error_rad", "is 4; must be at most 3.141592653589793")]
    [InlineData("""{ "tracking_error_ms": "50" }""", "$.safety.tracking_error_ms", "must be a number, found the string \"50\"")]
    [InlineData("""{ "current_limit_fraction": 0.01 }""", "$.safety.current_limit_fraction", "is 0.01; must be at least 0.05")]
    [InlineData("""{ "pot_distance_rad": 7 }""", "$.safety.pot_distance_rad", "is 7; must be at most 6.283185307179586")]
    [InlineData("""{ "pot_mismatch_ms": 10001 }""", "$.safety.pot_mismatch_ms", "is 10001; must be at most 10000")]
    [InlineData("""{ "module_silent_ms": null }""", "$.safety.module_silent_ms", "must be a number, not null")]
    [InlineData("""{ "deadline_misses_in_a_row": 2.5 }""", "$.safety.deadline_misses_in_a_row", "is 2.5; must be a whole number")]
    [InlineData("""{ "deadline_misses_in_a_row": 0 }""", "$.safety.deadline_misses_in_a_row", "is 0; must be at least 1")]
    [InlineData("""{ "master_timeout_ms": 0 }""", "$.safety.master_timeout_ms", "is 0; must be at least 1")]
    [InlineData("""{ "safe_state": "hold" }""", "$.safety.safe_state", "must be an object, found the string \"hold\"")]
    [InlineData("""{ "safe_state": { "tracking": "hold" } }""", "$.safety.safe_state.tracking", "unknown check (known: non_finite, module_silent, tracking_error, over_current, pot_mismatch, deadline_miss, module_fault, operator, master_timeout, watchdog_unarmed, host_stall, master_jump, plugin_fault)")]
    [InlineData("""{ "safe_state": { "over_current": 1 } }""", "$.safety.safe_state.over_current", "must be \"hold\" or \"torque_off\", found the number 1")]
    [InlineData("""{ "motors": [] }""", "$.safety.motors", "must be an object, found an array")]
    [InlineData("""{ "motors": { "right.elbow": 0.2 } }""", "$.safety.motors.right.elbow", "must be an object, found the number 0.2")]
    public void Each_bad_input_is_one_line_naming_the_file_the_JSON_path_and_the_problem(string safety, string path, string problem) =>
        AssertOneLine(safety, path, problem);

    [Fact]
    public void Thresholds_per_motor_override_the_robot_wide_ones_and_an_unknown_motor_is_refused_in_one_line()
    {
        var limits = Load("""{ "pot_distance_rad": 0.1, "motors": { "right.elbow": { "tracking_error_rad": 0.2 }, "left.elbow": { "pot_distance_rad": 0.3 } } }""");
        Assert.Equal(0.2, limits.TrackingErrorRadOf("right.elbow"));
        Assert.Equal(0.1, limits.PotDistanceRadOf("right.elbow"));
        Assert.Equal(0.3, limits.PotDistanceRadOf("left.elbow"));
        Assert.Equal(new SafetyLimits().TrackingErrorRad, limits.TrackingErrorRadOf("left.elbow"));
        Assert.Equal(5 * Math.PI / 180, new SafetyLimits().PotDistanceRadOf("right.elbow"));

        AssertOneLine("""{ "motors": { "right.knee": { "tracking_error_rad": 0.2 } } }""", "$.safety.motors.right.knee", $"no such motor (known: {LbMotors})");
        AssertOneLine("""{ "motors": { "right.elbow": { "pot_distance_rad": 0 } } }""", "$.safety.motors.right.elbow.pot_distance_rad", "is 0; must be at least 1E-06");
        AssertOneLine("""{ "motors": { "right.elbow": { "tracking_error_rad": 3.2 } } }""", "$.safety.motors.right.elbow.tracking_error_rad", "is 3.2; must be at most 3.141592653589793");
        AssertOneLine("""{ "motors": { "right.elbow": { "current_limit_fraction": 1 } } }""", "$.safety.motors.right.elbow.current_limit_fraction", "unknown field");
    }

    [Fact]
    public void The_motor_names_are_those_of_the_modules_section()
    {
        var json = RobotFiles.Json("lb-1.0.json");
        json.AsObject().Remove("modules");
        json["safety"] = JsonNode.Parse("""{ "motors": { "right.elbow": { "tracking_error_rad": 0.2 } } }""");
        var path = _files.Write(json);
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        Assert.Equal($"{path}: $.safety.motors.right.elbow: no such motor (the file's modules section names none)", ex.Message);
    }

    [Fact]
    public void The_bus_watchdog_must_be_on_and_no_longer_than_its_safety_limit()
    {
        Assert.Equal(30, new SafetyLimits().BusWatchdogMaxMs);
        Assert.Equal(30, RobotLoader.Load(RobotFiles.Shipped("lb-1.0.json")).Modules.WatchdogMs); // the limit itself loads

        AssertOneLine(
            null,
            "$.modules.watchdog_ms",
            "is 0, which switches the modules' bus watchdogs off; the safety supervisor needs 1 to 30 ms ($.safety.bus_watchdog_max_ms)",
            watchdogMs: 0);
        AssertOneLine(
            null,
            "$.modules.watchdog_ms",
            "is 100 ms, longer than $.safety.bus_watchdog_max_ms (30 ms): a module would drive on for 100 ms after the host stops",
            watchdogMs: 100);
        AssertOneLine(null, "$.modules.watchdog_ms", "is -1; must be at least 0", watchdogMs: -1);

        var relaxed = Load("""{ "bus_watchdog_max_ms": 100 }""", watchdogMs: 100);
        Assert.Equal(100, relaxed.BusWatchdogMaxMs);
        AssertOneLine("""{ "bus_watchdog_max_ms": 0 }""", "$.safety.bus_watchdog_max_ms", "is 0; must be at least 1");
        AssertOneLine("""{ "bus_watchdog_max_ms": 20 }""", "$.modules.watchdog_ms", "is 30 ms, longer than $.safety.bus_watchdog_max_ms (20 ms): a module would drive on for 30 ms after the host stops");
    }

    [Fact]
    public void The_second_stage_comes_after_the_first_and_no_later_than_its_safety_limit()
    {
        Assert.Equal(1000, new SafetyLimits().BusWatchdogOffMaxMs);
        Assert.Equal(500, RobotLoader.Load(RobotFiles.Shipped("lb-1.0.json")).Modules.WatchdogOffMs);
        Assert.Equal(ModuleLayout.DefaultWatchdogOffMs, LoadModules(WithSafety(null, null, watchdogOffMs: -2)).WatchdogOffMs); // -2: left out
        Assert.Equal(31, LoadModules(WithSafety(null, null, watchdogOffMs: 31)).WatchdogOffMs);

        AssertOneLine(
            null,
            "$.modules.watchdog_off_ms",
            "is 0, which the modules take as no hold stage (motors off at $.modules.watchdog_ms); give the time they switch their motors off, 31 to 1000 ms ($.safety.bus_watchdog_off_max_ms)",
            watchdogOffMs: 0);
        AssertOneLine(
            null,
            "$.modules.watchdog_off_ms",
            "is 30 ms, not longer than $.modules.watchdog_ms (30 ms): the modules switch their motors off this long after the host stops, after holding them from $.modules.watchdog_ms on",
            watchdogOffMs: 30);
        AssertOneLine(
            null,
            "$.modules.watchdog_off_ms",
            "is 1500 ms, longer than $.safety.bus_watchdog_off_max_ms (1000 ms): a module would hold its motors on its own for 1500 ms after the host stops",
            watchdogOffMs: 1500);
        AssertOneLine(null, "$.modules.watchdog_off_ms", "is -1; must be at least 0", watchdogOffMs: -1);
        AssertOneLine(null, "$.modules.watchdog_off_ms", "is 60001; must be at most 60000", watchdogOffMs: 60001);

        var relaxed = Load("""{ "bus_watchdog_off_max_ms": 2000 }""", watchdogOffMs: 1500);
        Assert.Equal(2000, relaxed.BusWatchdogOffMaxMs);
        AssertOneLine("""{ "bus_watchdog_off_max_ms": 0 }""", "$.safety.bus_watchdog_off_max_ms", "is 0; must be at least 1");
        AssertOneLine("""{ "bus_watchdog_off_max_ms": 400 }""", "$.modules.watchdog_off_ms", "is 500 ms, longer than $.safety.bus_watchdog_off_max_ms (400 ms): a module would hold its motors on its own for 500 ms after the host stops");

        // A first stage already refused is named alone, not again through the second.
        AssertOneLine(null, "$.modules.watchdog_ms", "is 600 ms, longer than $.safety.bus_watchdog_max_ms (30 ms): a module would drive on for 600 ms after the host stops", watchdogMs: 600);
    }

    [Fact]
    public void Every_problem_of_the_section_is_reported_at_once_and_nothing_is_loaded()
    {
        var json = WithSafety("""{ "over_current_ms": -1, "safe_state": { "tracking_error": "brake" }, "motors": { "right.knee": {} } }""", watchdogMs: null);
        var path = _files.Write(json);
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        Assert.Equal(["$.safety.motors.right.knee", "$.safety.over_current_ms", "$.safety.safe_state.tracking_error"], ex.Errors.Select(e => e.Path).Order(StringComparer.Ordinal));
        Assert.All(ex.Errors, e => Assert.Equal(path, e.File));
        Assert.StartsWith("3 problems:", ex.Message, StringComparison.Ordinal);
    }

    /// <summary>The LB-1.0 file with <paramref name="safety"/> as its safety section and the watchdog stages given (null: as shipped; <paramref name="watchdogOffMs"/> -2: left out).</summary>
    private static JsonNode WithSafety(string? safety, int? watchdogMs, int? watchdogOffMs = null)
    {
        var json = RobotFiles.Json("lb-1.0.json");
        if (safety is not null)
        {
            json["safety"] = JsonNode.Parse(safety);
        }

        if (watchdogMs is { } ms)
        {
            json["modules"]!["watchdog_ms"] = ms;
        }

        if (watchdogOffMs == -2)
        {
            json["modules"]!.AsObject().Remove("watchdog_off_ms");
        }
        else if (watchdogOffMs is { } off)
        {
            json["modules"]!["watchdog_off_ms"] = off;
        }

        return json;
    }

    private SafetyLimits Load(string safety, int? watchdogMs = null, int? watchdogOffMs = null) => RobotLoader.Load(_files.Write(WithSafety(safety, watchdogMs, watchdogOffMs))).Safety;

    private ModuleLayout LoadModules(JsonNode json) => RobotLoader.Load(_files.Write(json)).Modules;

    /// <summary>Loading fails (no definition) with exactly one problem, printed as the one line <c>file: path: problem</c>.</summary>
    private void AssertOneLine(string? safety, string jsonPath, string problem, int? watchdogMs = null, int? watchdogOffMs = null)
    {
        var path = _files.Write(WithSafety(safety, watchdogMs, watchdogOffMs));
        var ex = Assert.Throws<RobotDataException>(() => RobotLoader.Load(path));
        var error = Assert.Single(ex.Errors);
        Assert.Equal((path, jsonPath, problem), (error.File, error.Path, error.Message));
        Assert.Equal($"{path}: {jsonPath}: {problem}", ex.Message);
    }
}
