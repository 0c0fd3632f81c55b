using System.Globalization;

namespace RobotControl.Host.Harness;

/// <summary>
/// Faults to inject into the virtual robot, parsed from <c>ber=1e-5,reset=right.shoulder@5s,reset=left.forearm@8.5s</c>:
/// a bit-error rate on the wire and module resets (module named <c>arm.location</c> or by bus ID, at a run time).
/// </summary>
/// <param name="BitErrorRate">Probability that a bit on the wire flips.</param>
/// <param name="Resets">Module resets: which module and when (run time).</param>
public sealed record FaultInjection(double BitErrorRate, IReadOnlyList<ModuleReset> Resets)
{
    /// <summary>No faults.</summary>
    public static FaultInjection None { get; } = new(0, []);

    /// <summary>True when nothing is injected.</summary>
    public bool IsNone => BitErrorRate == 0 && Resets.Count == 0;

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
                default:
                    throw new FormatException($"--inject '{part}': unknown fault (ber=<rate>, reset=<module>@<time>)");
            }
        }

        return new FaultInjection(ber, resets);
    }

    /// <inheritdoc />
    public override string ToString() =>
        IsNone ? "none" : string.Join(",", (BitErrorRate > 0 ? [string.Create(CultureInfo.InvariantCulture, $"ber={BitErrorRate:G3}")] : Array.Empty<string>())
            .Concat(Resets.Select(r => string.Create(CultureInfo.InvariantCulture, $"reset={r.Module}@{r.At.TotalSeconds:0.###}s"))));
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
