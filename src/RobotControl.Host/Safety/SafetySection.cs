using System.Text.Json;

namespace RobotControl.Host.Safety;

/// <summary>
/// Reads the optional <c>safety</c> section of a robot file into <see cref="SafetyLimits"/>; absent fields keep their
/// defaults. Example:
/// <code>
/// "safety": { "tracking_error_rad": 0.35, "tracking_error_ms": 50, "current_limit_fraction": 0.95,
///             "over_current_ms": 50, "pot_distance_rad": 0.087, "pot_mismatch_ms": 10,
///             "module_silent_ms": 10, "deadline_misses_in_a_row": 10, "master_timeout_ms": 50, "bus_watchdog_max_ms": 30,
///             "safe_state": { "tracking_error": "hold", "over_current": "torque_off" },
///             "motors": { "right.elbow": { "tracking_error_rad": 0.2, "pot_distance_rad": 0.1 } } }
/// </code>
/// </summary>
public static class SafetySection
{
    private static readonly string[] Fields =
        ["tracking_error_rad", "tracking_error_ms", "current_limit_fraction", "over_current_ms", "pot_distance_rad", "pot_mismatch_ms", "module_silent_ms", "deadline_misses_in_a_row", "master_timeout_ms", "bus_watchdog_max_ms", "safe_state", "motors"];

    private static readonly string[] MotorFields = ["tracking_error_rad", "pot_distance_rad"];

    /// <summary>Reads the <c>safety</c> section of the robot file at <paramref name="path"/> (defaults without one).</summary>
    /// <param name="path">The robot file.</param>
    /// <param name="motors">The robot's motor names (<c>arm.motor</c>): the only keys <c>motors</c> may have (null: not checked).</param>
    /// <exception cref="FormatException">A field is unknown, of the wrong type or out of range (one line naming the file and field).</exception>
    public static SafetyLimits Load(string path, IReadOnlyCollection<string>? motors = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(path);
        using var doc = JsonDocument.Parse(File.ReadAllText(path), new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        return doc.RootElement.TryGetProperty("safety", out var section) ? Parse(section, path, motors) : new SafetyLimits();
    }

    /// <summary>Reads a <c>safety</c> section; <paramref name="file"/> names it in messages.</summary>
    /// <param name="section">The section.</param>
    /// <param name="file">The file, for messages.</param>
    /// <param name="motors">The robot's motor names (<c>arm.motor</c>): the only keys <c>motors</c> may have (null: not checked).</param>
    /// <exception cref="FormatException">A field is unknown, of the wrong type or out of range.</exception>
    public static SafetyLimits Parse(JsonElement section, string file, IReadOnlyCollection<string>? motors = null)
    {
        if (section.ValueKind != JsonValueKind.Object)
        {
            throw new FormatException($"{file}: safety: expected an object");
        }

        foreach (var p in section.EnumerateObject())
        {
            if (Array.IndexOf(Fields, p.Name) < 0)
            {
                throw new FormatException($"{file}: safety.{p.Name}: unknown field (known: {string.Join(", ", Fields)})");
            }
        }

        var d = new SafetyLimits();
        return new SafetyLimits
        {
            TrackingErrorRad = Number(section, "tracking_error_rad", d.TrackingErrorRad, 1e-6, Math.PI, file),
            TrackingErrorMs = Number(section, "tracking_error_ms", d.TrackingErrorMs, 0, 10_000, file),
            CurrentLimitFraction = Number(section, "current_limit_fraction", d.CurrentLimitFraction, 0.05, 2, file),
            OverCurrentMs = Number(section, "over_current_ms", d.OverCurrentMs, 0, 10_000, file),
            PotDistanceRad = Number(section, "pot_distance_rad", d.PotDistanceRad, 1e-6, 2 * Math.PI, file),
            PotMismatchMs = Number(section, "pot_mismatch_ms", d.PotMismatchMs, 0, 10_000, file),
            ModuleSilentMs = Number(section, "module_silent_ms", d.ModuleSilentMs, 0, 10_000, file),
            DeadlineMissesInARow = (int)Number(section, "deadline_misses_in_a_row", d.DeadlineMissesInARow, 1, 100_000, file, integer: true),
            MasterTimeoutMs = Number(section, "master_timeout_ms", d.MasterTimeoutMs, 1, 10_000, file),
            BusWatchdogMaxMs = Number(section, "bus_watchdog_max_ms", d.BusWatchdogMaxMs, 1, 60_000, file),
            SafeStates = SafeStates(section, file),
            Motors = PerMotor(section, file, motors),
        };
    }

    /// <summary>
    /// The robot file's bus watchdog period (<c>modules.watchdog_ms</c>) must be on and no longer than
    /// <see cref="SafetyLimits.BusWatchdogMaxMs"/>: the modules stop their motors that long after the host stops.
    /// </summary>
    /// <exception cref="FormatException">It is 0 (off) or too long (one line naming the file and both fields).</exception>
    public static void CheckWatchdog(SafetyLimits limits, int watchdogMs, string file)
    {
        ArgumentNullException.ThrowIfNull(limits);
        if (watchdogMs <= 0)
        {
            throw new FormatException($"{file}: modules.watchdog_ms: {watchdogMs} switches the modules' bus watchdogs off; the safety supervisor needs 1 to {limits.BusWatchdogMaxMs:0.###} ms (safety.bus_watchdog_max_ms)");
        }

        if (watchdogMs > limits.BusWatchdogMaxMs)
        {
            throw new FormatException($"{file}: modules.watchdog_ms: {watchdogMs} ms is longer than safety.bus_watchdog_max_ms ({limits.BusWatchdogMaxMs:0.###} ms): a module would drive on for {watchdogMs} ms after the host stops");
        }
    }

    private static Dictionary<string, MotorSafetyLimits> PerMotor(JsonElement section, string file, IReadOnlyCollection<string>? motors)
    {
        var result = new Dictionary<string, MotorSafetyLimits>(StringComparer.Ordinal);
        if (!section.TryGetProperty("motors", out var map))
        {
            return result;
        }

        if (map.ValueKind != JsonValueKind.Object)
        {
            throw new FormatException($"{file}: safety.motors: expected an object of motor (arm.motor) -> {{ {string.Join(", ", MotorFields)} }}");
        }

        foreach (var p in map.EnumerateObject())
        {
            var at = $"motors.{p.Name}";
            if (motors is not null && !motors.Contains(p.Name))
            {
                throw new FormatException($"{file}: safety.{at}: no such motor (known: {string.Join(", ", motors)})");
            }

            if (p.Value.ValueKind != JsonValueKind.Object)
            {
                throw new FormatException($"{file}: safety.{at}: expected an object with {string.Join(" and/or ", MotorFields)}");
            }

            foreach (var f in p.Value.EnumerateObject())
            {
                if (Array.IndexOf(MotorFields, f.Name) < 0)
                {
                    throw new FormatException($"{file}: safety.{at}.{f.Name}: unknown field (known: {string.Join(", ", MotorFields)})");
                }
            }

            result[p.Name] = new MotorSafetyLimits(
                p.Value.TryGetProperty("tracking_error_rad", out _) ? Number(p.Value, "tracking_error_rad", 0, 1e-6, Math.PI, file, prefix: $"{at}.") : null,
                p.Value.TryGetProperty("pot_distance_rad", out _) ? Number(p.Value, "pot_distance_rad", 0, 1e-6, 2 * Math.PI, file, prefix: $"{at}.") : null);
        }

        return result;
    }

    private static double Number(JsonElement section, string name, double fallback, double min, double max, string file, bool integer = false, string prefix = "")
    {
        if (!section.TryGetProperty(name, out var v))
        {
            return fallback;
        }

        if (v.ValueKind != JsonValueKind.Number || !v.TryGetDouble(out var x) || x < min || x > max || (integer && x != Math.Floor(x)))
        {
            throw new FormatException($"{file}: safety.{prefix}{name}: expected {(integer ? "an integer" : "a number")} from {min} to {max}, got {v.GetRawText()}");
        }

        return x;
    }

    private static Dictionary<SafetyCheck, SafeState> SafeStates(JsonElement section, string file)
    {
        var states = new Dictionary<SafetyCheck, SafeState>(SafetyLimits.DefaultSafeStates);
        if (!section.TryGetProperty("safe_state", out var map))
        {
            return states;
        }

        if (map.ValueKind != JsonValueKind.Object)
        {
            throw new FormatException($"{file}: safety.safe_state: expected an object of check -> \"hold\" or \"torque_off\"");
        }

        foreach (var p in map.EnumerateObject())
        {
            var check = Enum.GetValues<SafetyCheck>().Where(c => c.Name() == p.Name).Cast<SafetyCheck?>().FirstOrDefault()
                ?? throw new FormatException($"{file}: safety.safe_state.{p.Name}: unknown check (known: {string.Join(", ", Enum.GetValues<SafetyCheck>().Select(c => c.Name()))})");
            states[check] = p.Value.ValueKind == JsonValueKind.String ? p.Value.GetString() switch
            {
                "hold" => SafeState.Hold,
                "torque_off" => SafeState.TorqueOff,
                _ => throw new FormatException($"{file}: safety.safe_state.{p.Name}: expected \"hold\" or \"torque_off\", got {p.Value.GetRawText()}"),
            }
            : throw new FormatException($"{file}: safety.safe_state.{p.Name}: expected \"hold\" or \"torque_off\", got {p.Value.GetRawText()}");
        }

        return states;
    }
}
