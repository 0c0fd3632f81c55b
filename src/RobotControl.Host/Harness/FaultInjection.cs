using System.Globalization;

namespace RobotControl.Host.Harness;

/// <summary>
/// Faults to inject into the virtual robot, parsed from <c>ber=1e-5,reset=right.shoulder@5s,stuck=right.elbow@5s</c>:
/// a bit-error rate on the wire, module resets (module named <c>arm.location</c> or by bus ID, at a run time), and
/// the safety faults (<see cref="TimedFaultKind"/>): <c>stall=100ms@5s</c> (the host stops for that long),
/// <c>stuck=right.elbow@5s</c> (locked rotor), <c>current=right.elbow@5s</c> (current spike at the sensor),
/// <c>nan=ik_right@5s</c> (the plug-in's arm gets a NaN setpoint), <c>pot=right.elbow@5s</c> (the joint pot fails), <c>silent=right.forearm@5s</c> (the module's
/// transmit line breaks: its replies stop), <c>watchdog=right.forearm@5s</c> (the module's bus watchdog is switched off
/// by a write that did not come from the host), <c>jump=touch_right:50mm@5s</c> (an input device's reading jumps 50 mm along x in one sample and
/// stays offset) and <c>stale=touch_right@5s</c> (an input device stops giving new readings: the master timeout); these two
/// go to the named plug-in instance through the SDK's <c>IFaultInjectable</c> (a simulated Touch takes them).
/// </summary>
/// <param name="BitErrorRate">Probability that a bit on the wire flips.</param>
/// <param name="Resets">Module resets: which module and when (run time).</param>
/// <param name="Timed">Safety faults at run times.</param>
public sealed record FaultInjection(double BitErrorRate, IReadOnlyList<ModuleReset> Resets, IReadOnlyList<TimedFault>? Timed = null)
{
    /// <summary>No faults.</summary>
    public static FaultInjection None { get; } = new(0, []);

    /// <summary>The syntax, for <c>--help</c> and messages.</summary>
    public const string Syntax = "ber=<rate>, reset=<module>@<time>, silent=<module>@<time>, watchdog=<module>@<time>, stall=<duration>@<time>, stuck=<arm.motor>@<time>, current=<arm.motor>@<time>, pot=<arm.motor>@<time>, nan=<plug-in>@<time>, jump=<touch>:<distance>mm@<time>, stale=<touch>@<time>";

    /// <summary>The safety faults (empty when none).</summary>
    public IReadOnlyList<TimedFault> TimedFaults => Timed ?? [];

    /// <summary>True when nothing is injected.</summary>
    public bool IsNone => BitErrorRate == 0 && Resets.Count == 0 && TimedFaults.Count == 0;

    /// <summary>Parses the <c>--inject</c> text.</summary>
    /// <exception cref="FormatException">The text is malformed (the message names the part).</exception>
    public static FaultInjection Parse(string? text)
    {
        if (string.IsNullOrWhiteSpace(text))
        {
            return None;
        }

        var ber = 0.0;
        var resets = new List<ModuleReset>();
        var timed = new List<TimedFault>();
        foreach (var part in text.Split(',', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries))
        {
            var eq = part.IndexOf('=', StringComparison.Ordinal);
            var key = eq > 0 ? part[..eq].ToLowerInvariant() : "";
            var value = eq > 0 ? part[(eq + 1)..] : "";
            switch (key)
            {
                case "ber":
                    if (!double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out ber) || !(ber >= 0 && ber < 0.5))
                    {
                        throw new FormatException($"--inject '{part}': ber must be a probability below 0.5, e.g. ber=1e-5");
                    }

                    break;
                case "reset":
                    var at = value.LastIndexOf('@');
                    if (at <= 0)
                    {
                        throw new FormatException($"--inject '{part}': expected reset=<arm.location or id>@<time>, e.g. reset=right.shoulder@5s");
                    }

                    resets.Add(new ModuleReset(value[..at], RunDuration.Parse(value[(at + 1)..])));
                    break;
                case "silent":
                case "watchdog":
                case "stall":
                case "stuck":
                case "current":
                case "nan":
                case "pot":
                case "jump":
                case "stale":
                    timed.Add(ParseTimed(part, key, value));
                    break;
                default:
                    throw new FormatException($"--inject '{part}': unknown fault (known: {Syntax})");
            }
        }

        return new FaultInjection(ber, resets, timed);
    }

    /// <inheritdoc />
    public override string ToString() =>
        IsNone ? "none" : string.Join(",", (BitErrorRate > 0 ? [string.Create(CultureInfo.InvariantCulture, $"ber={BitErrorRate:G3}")] : Array.Empty<string>())
            .Concat(Resets.Select(r => string.Create(CultureInfo.InvariantCulture, $"reset={r.Module}@{r.At.TotalSeconds:0.###}s")))
            .Concat(TimedFaults.Select(f => f.ToString())));

    private static TimedFault ParseTimed(string part, string key, string value)
    {
        var at = value.LastIndexOf('@');
        if (at <= 0)
        {
            throw new FormatException($"--inject '{part}': expected {key}=<{key switch { "stall" => "duration", "nan" => "plug-in", "silent" or "watchdog" => "arm.location or id", "jump" => "touch>:<distance>mm", "stale" => "touch", _ => "arm.motor" }}>@<time>, e.g. {key}={key switch { "stall" => "100ms", "nan" => "ik_right", "silent" or "watchdog" => "right.forearm", "jump" => "touch_right:50mm", "stale" => "touch_right", _ => "right.elbow" }}@5s");
        }

        var kind = key switch { "silent" => TimedFaultKind.Silent, "watchdog" => TimedFaultKind.Watchdog, "stall" => TimedFaultKind.Stall, "stuck" => TimedFaultKind.Stuck, "current" => TimedFaultKind.Current, "pot" => TimedFaultKind.Pot, "jump" => TimedFaultKind.Jump, "stale" => TimedFaultKind.Stale, _ => TimedFaultKind.Nan };
        var target = value[..at];
        if (kind == TimedFaultKind.Jump)
        {
            var colon = target.LastIndexOf(':');
            var distance = colon > 0 ? target[(colon + 1)..].Trim().ToLowerInvariant() : "";
            if (colon <= 0 || !distance.EndsWith("mm", StringComparison.Ordinal)
                || !double.TryParse(distance[..^2], NumberStyles.Float, CultureInfo.InvariantCulture, out var mm) || !double.IsFinite(mm) || mm == 0 || Math.Abs(mm) > 1000)
            {
                throw new FormatException($"--inject '{part}': expected jump=<touch>:<distance>mm@<time> with a distance from -1000 to 1000 mm other than 0, e.g. jump=touch_right:50mm@5s");
            }

            return new TimedFault(kind, target[..colon], TimeSpan.Zero, RunDuration.Parse(value[(at + 1)..]), mm);
        }

        var stall = kind == TimedFaultKind.Stall ? RunDuration.Parse(target) : TimeSpan.Zero;
        if (kind == TimedFaultKind.Stall && stall <= TimeSpan.Zero)
        {
            throw new FormatException($"--inject '{part}': the stall must last longer than 0, e.g. stall=100ms@5s");
        }

        return new TimedFault(kind, kind == TimedFaultKind.Stall ? string.Empty : target, stall, RunDuration.Parse(value[(at + 1)..]));
    }
}

/// <summary>The safety faults <c>--inject</c> knows.</summary>
public enum TimedFaultKind
{
    /// <summary>A module's transmit line breaks: its replies stop reaching the host (it still hears the host).</summary>
    Silent,

    /// <summary>A module's bus watchdog is switched off (<c>bus_watchdog</c> 0) by a write that did not come from the host.</summary>
    Watchdog,

    /// <summary>The host stops (no bus traffic, no ticks) for a duration.</summary>
    Stall,

    /// <summary>A motor's rotor locks (a jammed joint).</summary>
    Stuck,

    /// <summary>A motor's current sensor reads twice its limit more (a spike).</summary>
    Current,

    /// <summary>A plug-in's arm gets NaN joint setpoints.</summary>
    Nan,

    /// <summary>A motor's joint pot fails: its wiper opens and the ADC reads 0 whatever the joint does.</summary>
    Pot,

    /// <summary>An input device's reading jumps along x in one sample (and stays offset); the SDK's <c>DeviceFaultKind.Jump</c>.</summary>
    Jump,

    /// <summary>An input device stops giving new readings (its sample age grows: the master timeout); the SDK's <c>DeviceFaultKind.Stale</c>.</summary>
    Stale,
}

/// <summary>One safety fault.</summary>
/// <param name="Kind">What.</param>
/// <param name="Target">Motor (<c>arm.motor</c>), module or plug-in instance; empty for a stall.</param>
/// <param name="Duration">How long a stall lasts.</param>
/// <param name="At">When, in run time.</param>
/// <param name="JumpMm">How far a jump moves the reading, mm.</param>
public sealed record TimedFault(TimedFaultKind Kind, string Target, TimeSpan Duration, TimeSpan At, double JumpMm = 0)
{
    /// <inheritdoc />
    public override string ToString() => Kind switch
    {
        TimedFaultKind.Jump => string.Create(CultureInfo.InvariantCulture, $"jump={Target}:{JumpMm:0.###}mm@{At.TotalSeconds:0.###}s"),
        TimedFaultKind.Stall => string.Create(CultureInfo.InvariantCulture, $"stall={Duration.TotalMilliseconds:0.###}ms@{At.TotalSeconds:0.###}s"),
        _ => string.Create(CultureInfo.InvariantCulture, $"{Kind.ToString().ToLowerInvariant()}={Target}@{At.TotalSeconds:0.###}s"),
    };
}

/// <summary>One injected module reset.</summary>
/// <param name="Module">Module as <c>arm.location</c> (e.g. <c>right.shoulder</c>) or bus ID.</param>
/// <param name="At">When, in run time.</param>
public sealed record ModuleReset(string Module, TimeSpan At);

/// <summary>Parses durations such as <c>20s</c>, <c>500ms</c>, <c>2m</c> or <c>1.5</c> (seconds).</summary>
public static class RunDuration
{
    /// <summary>Parses a duration.</summary>
    /// <exception cref="FormatException">Not a non-negative finite duration.</exception>
    public static TimeSpan Parse(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var t = text.Trim().ToLowerInvariant();
        var (number, scale) = t.EndsWith("ms", StringComparison.Ordinal) ? (t[..^2], 1e-3)
            : t.EndsWith('s') ? (t[..^1], 1.0)
            : t.EndsWith('m') ? (t[..^1], 60.0)
            : (t, 1.0);
        if (!double.TryParse(number, NumberStyles.Float, CultureInfo.InvariantCulture, out var value) || !double.IsFinite(value) || value < 0
            || value * scale >= TimeSpan.MaxValue.TotalSeconds)
        {
            throw new FormatException($"'{text}' is not a duration (e.g. 20s, 500ms, 2m)");
        }

        return TimeSpan.FromSeconds(value * scale);
    }
}
