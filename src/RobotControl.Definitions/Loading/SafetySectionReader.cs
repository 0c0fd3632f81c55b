using System.Text.Json;
using RobotControl.Definitions.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Definitions.Loading;

/// <summary>
/// Reads and validates a robot file's optional <c>safety</c> section (the safety supervisor's thresholds and safe
/// states, see <see cref="SafetyLimits"/>; absent fields keep their defaults) and checks the <c>modules</c> section's
/// bus watchdog against it. Example:
/// <code>
/// "safety": { "tracking_error_rad": 0.35, "tracking_error_ms": 50, "current_limit_fraction": 0.95,
///             "over_current_ms": 50, "pot_distance_rad": 0.087, "pot_mismatch_ms": 10,
///             "module_silent_ms": 10, "deadline_misses_in_a_row": 10, "master_timeout_ms": 50, "master_speed_max_mm_s": 2000,
///             "bus_watchdog_max_ms": 30, "bus_watchdog_off_max_ms": 1000,
///             "safe_state": { "tracking_error": "hold", "over_current": "torque_off" },
///             "motors": { "right.elbow": { "tracking_error_rad": 0.2, "pot_distance_rad": 0.1 } } }
/// </code>
/// </summary>
internal static class SafetySectionReader
{
    private const double MinRad = 1e-6;
    private const double MaxMs = 10_000;
    private const double MaxTrackingErrorRad = Math.PI;
    private const double MaxPotDistanceRad = 2 * Math.PI;

    /// <summary>Reads the section (defaults without one) and checks <c>modules.watchdog_ms</c> and <c>modules.watchdog_off_ms</c> against it.</summary>
    /// <param name="root">The robot file's root object.</param>
    /// <param name="modules">The file's modules, as read.</param>
    /// <param name="motorNames">The robot's motor names (<c>arm.motor</c>): the only keys <c>safety.motors</c> may have.</param>
    public static SafetyLimits Read(JsonFieldReader root, ModuleLayout modules, IReadOnlyList<string> motorNames)
    {
        var section = OptionalObject(root, "safety");
        var limits = section is null ? new SafetyLimits() : ReadLimits(section, motorNames);
        if (root.Has("modules"))
        {
            CheckWatchdog(root.Sink, limits, modules.WatchdogMs, root.FieldPath("modules.watchdog_ms"), root.FieldPath("safety.bus_watchdog_max_ms"));
            CheckWatchdogOff(root.Sink, limits, modules, root.FieldPath("modules.watchdog_off_ms"), root.FieldPath("modules.watchdog_ms"), root.FieldPath("safety.bus_watchdog_off_max_ms"));
        }

        return limits;
    }

    /// <summary>The names of the motors <paramref name="modules"/> drive (<c>arm.motor</c>), skipping references the loader refused.</summary>
    public static List<string> MotorNames(ModuleLayout modules, IReadOnlyList<ArmPlacement> arms, IReadOnlyList<ActuatorDefinition> actuators, IReadOnlyList<JointDefinition> joints) =>
        [.. from module in modules.Modules
            where module.Arm >= 0
            from motor in module.Motors
            where motor.ActuatorIndex >= 0
            select MotorName.Full(arms[module.Arm].Name, MotorName.Of(actuators[motor.ActuatorIndex], joints))];

    private static SafetyLimits ReadLimits(JsonFieldReader s, IReadOnlyList<string> motorNames)
    {
        var d = new SafetyLimits();
        double Field(string name, double min, double max, double fallback) =>
            s.NumberOrNull(name, min, max, required: false, allowNull: false) ?? fallback;

        var limits = new SafetyLimits
        {
            TrackingErrorRad = Field("tracking_error_rad", MinRad, MaxTrackingErrorRad, d.TrackingErrorRad),
            TrackingErrorMs = Field("tracking_error_ms", 0, MaxMs, d.TrackingErrorMs),
            CurrentLimitFraction = Field("current_limit_fraction", 0.05, 2, d.CurrentLimitFraction),
            OverCurrentMs = Field("over_current_ms", 0, MaxMs, d.OverCurrentMs),
            PotDistanceRad = Field("pot_distance_rad", MinRad, MaxPotDistanceRad, d.PotDistanceRad),
            PotMismatchMs = Field("pot_mismatch_ms", 0, MaxMs, d.PotMismatchMs),
            ModuleSilentMs = Field("module_silent_ms", 0, MaxMs, d.ModuleSilentMs),
            DeadlineMissesInARow = s.IntegerOrNull("deadline_misses_in_a_row", 1, 100_000, required: false) ?? d.DeadlineMissesInARow,
            MasterTimeoutMs = Field("master_timeout_ms", 1, MaxMs, d.MasterTimeoutMs),
            MasterSpeedMaxMmPerS = Field("master_speed_max_mm_s", 100, 100_000, d.MasterSpeedMaxMmPerS),
            BusWatchdogMaxMs = Field("bus_watchdog_max_ms", 1, ModuleLayout.MaxWatchdogMs, d.BusWatchdogMaxMs),
            BusWatchdogOffMaxMs = Field("bus_watchdog_off_max_ms", 1, ModuleLayout.MaxWatchdogMs, d.BusWatchdogOffMaxMs),
            SafeStates = ReadSafeStates(OptionalObject(s, "safe_state")),
            Motors = ReadMotors(OptionalObject(s, "motors"), motorNames),
        };
        s.RejectUnknownFields();
        return limits;
    }

    private static Dictionary<SafetyCheck, SafeState> ReadSafeStates(JsonFieldReader? map)
    {
        var states = new Dictionary<SafetyCheck, SafeState>(SafetyLimits.DefaultSafeStates);
        if (map is null)
        {
            return states;
        }

        var checks = Enum.GetValues<SafetyCheck>();
        var safeStates = Enum.GetValues<SafeState>();
        foreach (var (name, value) in map.Properties())
        {
            var path = map.FieldPath(name);
            var check = Array.FindIndex(checks, c => c.Name() == name);
            if (check < 0)
            {
                map.Sink.Add(path, $"unknown check (known: {string.Join(", ", checks.Select(c => c.Name()))})");
                continue;
            }

            var state = value.ValueKind == JsonValueKind.String ? Array.FindIndex(safeStates, s => s.Name() == value.GetString()) : -1;
            if (state < 0)
            {
                map.Sink.Add(path, $"must be {string.Join(" or ", safeStates.Select(s => $"\"{s.Name()}\""))}, found {JsonFieldReader.Describe(value)}");
                continue;
            }

            states[checks[check]] = safeStates[state];
        }

        return states;
    }

    private static Dictionary<string, MotorSafetyLimits> ReadMotors(JsonFieldReader? map, IReadOnlyList<string> motorNames)
    {
        var result = new Dictionary<string, MotorSafetyLimits>(StringComparer.Ordinal);
        if (map is null)
        {
            return result;
        }

        foreach (var (name, value) in map.Properties())
        {
            var path = map.FieldPath(name);
            if (!motorNames.Contains(name))
            {
                map.Sink.Add(path, motorNames.Count == 0 ? "no such motor (the file's modules section names none)" : $"no such motor (known: {string.Join(", ", motorNames)})");
                continue;
            }

            var m = new JsonFieldReader(map.Sink, value, path);
            if (!m.IsObject)
            {
                map.Sink.Add(path, $"must be an object, found {JsonFieldReader.Describe(value)}");
                continue;
            }

            result[name] = new MotorSafetyLimits(
                m.NumberOrNull("tracking_error_rad", MinRad, MaxTrackingErrorRad, required: false, allowNull: false),
                m.NumberOrNull("pot_distance_rad", MinRad, MaxPotDistanceRad, required: false, allowNull: false));
            m.RejectUnknownFields();
        }

        return result;
    }

    /// <summary>
    /// The bus watchdog period (<c>modules.watchdog_ms</c>) must be on and no longer than
    /// <see cref="SafetyLimits.BusWatchdogMaxMs"/>: the modules stop their motors that long after the host stops.
    /// Not checked when either value was already refused.
    /// </summary>
    private static void CheckWatchdog(JsonProblemSink sink, SafetyLimits limits, int watchdogMs, string watchdogPath, string maxPath)
    {
        if (sink.HasProblemAt(watchdogPath) || sink.HasProblemAt(maxPath))
        {
            return;
        }

        var max = limits.BusWatchdogMaxMs;
        if (watchdogMs <= 0)
        {
            sink.Add(watchdogPath, $"is {watchdogMs}, which switches the modules' bus watchdogs off; the safety supervisor needs 1 to {max:0.###} ms ({maxPath})");
        }
        else if (watchdogMs > max)
        {
            sink.Add(watchdogPath, $"is {watchdogMs} ms, longer than {maxPath} ({max:0.###} ms): a module would drive on for {watchdogMs} ms after the host stops");
        }
    }

    /// <summary>
    /// The bus watchdog's second stage (<c>modules.watchdog_off_ms</c>, the modules' <c>bus_watchdog_off</c>) must
    /// come after the first (<c>modules.watchdog_ms</c>: the modules hold, then switch their motors off) and no later
    /// than <see cref="SafetyLimits.BusWatchdogOffMaxMs"/>. 0 is refused too: the modules would read it as "no hold
    /// stage", which the file did not say. Not checked when any of the values was already refused.
    /// </summary>
    private static void CheckWatchdogOff(JsonProblemSink sink, SafetyLimits limits, ModuleLayout modules, string offPath, string watchdogPath, string maxPath)
    {
        if (sink.HasProblemAt(offPath) || sink.HasProblemAt(watchdogPath) || sink.HasProblemAt(maxPath))
        {
            return;
        }

        var (off, watchdog, max) = (modules.WatchdogOffMs, modules.WatchdogMs, limits.BusWatchdogOffMaxMs);
        if (off == 0)
        {
            sink.Add(offPath, $"is 0, which the modules take as no hold stage (motors off at {watchdogPath}); give the time they switch their motors off, {watchdog + 1} to {max:0.###} ms ({maxPath})");
        }
        else if (off <= watchdog)
        {
            sink.Add(offPath, $"is {off} ms, not longer than {watchdogPath} ({watchdog} ms): the modules switch their motors off this long after the host stops, after holding them from {watchdogPath} on");
        }
        else if (off > max)
        {
            sink.Add(offPath, $"is {off} ms, longer than {maxPath} ({max:0.###} ms): a module would hold its motors on its own for {off} ms after the host stops");
        }
    }

    /// <summary>An optional object field: null when absent; present, it must be an object (null included).</summary>
    private static JsonFieldReader? OptionalObject(JsonFieldReader r, string name) =>
        r.Object(name, required: r.Raw(name, required: false) is not null);
}
