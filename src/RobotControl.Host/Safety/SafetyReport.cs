using System.Text.Json;
using RobotControl.Definitions.Model;

namespace RobotControl.Host.Safety;

/// <summary>
/// The safety section of a run report: <c>{"final_run_level", "run_levels": [{"time_s", "from", "to", "source",
/// "reason"}], "trips": [{"time_s", "check", "joint", "measured", "limit", "unit", "action", "soft"}], "step_cap_hits",
/// "largest_capped_step_rad", "pedal_down_s", "re_engagements"}</c>. Times are seconds from the start of the run
/// (negative: while the session came up).
/// </summary>
/// <param name="FinalRunLevel">The run level at the end.</param>
/// <param name="RunLevels">Every run-level change.</param>
/// <param name="Trips">Every trip.</param>
/// <param name="StepCapHits">Goals the step cap shortened.</param>
/// <param name="LargestCappedStepRad">The largest step the cap shortened, radians (0: none).</param>
/// <param name="PedalDownSeconds">Time of the run spent at PEDAL_DOWN, seconds (teleoperation driving the arms).</param>
/// <param name="ReEngagements">Pedal presses the harness made after soft trips (<see cref="Harness.RunOptions.ReEngageAfter"/>).</param>
public sealed record SafetyReport(RunLevel FinalRunLevel, IReadOnlyList<SafetyReport.Level> RunLevels, IReadOnlyList<SafetyReport.TripEntry> Trips, long StepCapHits, double LargestCappedStepRad, double PedalDownSeconds = 0, int ReEngagements = 0)
{
    /// <summary>What <paramref name="supervisor"/> saw, times from its origin; the run ended <paramref name="endSeconds"/> after it.</summary>
    public static SafetyReport Of(SafetySupervisor supervisor, double endSeconds = 0, int reEngagements = 0)
    {
        ArgumentNullException.ThrowIfNull(supervisor);
        var levels = supervisor.History.Select(h => new Level(supervisor.Seconds(h.Timestamp), h.From, h.To, h.Source, h.Reason)).ToList();
        return new SafetyReport(
            supervisor.Level,
            levels,
            [.. supervisor.Trips.Select(t => new TripEntry(supervisor.Seconds(t.Timestamp), t.Check, t.Joint, t.Measured, t.Limit, t.Unit, t.Action, t.Soft))],
            supervisor.Robot.StepCapHits,
            supervisor.Robot.LargestCappedStepRad,
            TimeAt(RunLevel.PedalDown, levels, endSeconds),
            reEngagements);
    }

    /// <summary>Seconds spent at <paramref name="level"/> between 0 and <paramref name="endSeconds"/>, from the changes.</summary>
    public static double TimeAt(RunLevel level, IReadOnlyList<Level> levels, double endSeconds)
    {
        ArgumentNullException.ThrowIfNull(levels);
        var total = 0.0;
        for (var i = 0; i < levels.Count; i++)
        {
            if (levels[i].To != level)
            {
                continue;
            }

            var from = Math.Max(0, levels[i].TimeSeconds);
            var to = Math.Min(endSeconds, i + 1 < levels.Count ? levels[i + 1].TimeSeconds : endSeconds);
            total += Math.Max(0, to - from);
        }

        return total;
    }

    /// <summary>Writes the <c>safety</c> object.</summary>
    public void Write(Utf8JsonWriter w)
    {
        ArgumentNullException.ThrowIfNull(w);
        w.WriteStartObject("safety");
        w.WriteString("final_run_level", FinalRunLevel.Name());
        w.WriteStartArray("run_levels");
        foreach (var l in RunLevels)
        {
            w.WriteStartObject();
            w.WriteNumber("time_s", Math.Round(l.TimeSeconds, 4));
            w.WriteString("from", l.From.Name());
            w.WriteString("to", l.To.Name());
            w.WriteString("source", l.Source);
            w.WriteString("reason", l.Reason);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteStartArray("trips");
        foreach (var t in Trips)
        {
            w.WriteStartObject();
            w.WriteNumber("time_s", Math.Round(t.TimeSeconds, 4));
            w.WriteString("check", t.Check.Name());
            w.WriteString("joint", t.Joint);
            WriteNumber(w, "measured", t.Measured);
            WriteNumber(w, "limit", t.Limit);
            w.WriteString("unit", t.Unit);
            w.WriteString("action", t.Action.Name());
            w.WriteBoolean("soft", t.Soft);
            w.WriteEndObject();
        }

        w.WriteEndArray();
        w.WriteNumber("step_cap_hits", StepCapHits);
        w.WriteNumber("largest_capped_step_rad", Math.Round(LargestCappedStepRad, 6));
        w.WriteNumber("pedal_down_s", Math.Round(PedalDownSeconds, 4));
        w.WriteNumber("re_engagements", ReEngagements);
        w.WriteEndObject();
    }

    /// <summary>Console lines: the run levels gone through and every trip.</summary>
    public IEnumerable<string> Lines()
    {
        yield return FormattableString.Invariant($"  safety: final run level {FinalRunLevel.Name()}; levels {string.Join(" -> ", RunLevels.Select(l => l.From.Name()).Take(1).Concat(RunLevels.Select(l => l.To.Name())))}; step cap hits {StepCapHits}; trips {Trips.Count} ({Trips.Count(t => t.Soft)} soft); {PedalDownSeconds:F3} s at PEDAL_DOWN; re-engaged {ReEngagements}");
        foreach (var t in Trips)
        {
            yield return FormattableString.Invariant($"    {t.TimeSeconds,8:F3} s  {(t.Check.Name() + " " + t.Joint).TrimEnd()}: {t.Measured:G4} {t.Unit} (limit {t.Limit:G4}) -> {t.Action.Name()}{(t.Soft ? ", PEDAL_UP" : string.Empty)}");
        }
    }

    private static void WriteNumber(Utf8JsonWriter w, string name, double value)
    {
        if (double.IsFinite(value))
        {
            w.WriteNumber(name, Math.Round(value, 6));
        }
        else
        {
            w.WriteString(name, value.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
    }

    /// <summary>One run-level change.</summary>
    /// <param name="TimeSeconds">Seconds from the start of the run.</param>
    /// <param name="From">Level before.</param>
    /// <param name="To">Level after.</param>
    /// <param name="Source">Who asked.</param>
    /// <param name="Reason">Why.</param>
    public sealed record Level(double TimeSeconds, RunLevel From, RunLevel To, string Source, string Reason);

    /// <summary>One trip.</summary>
    /// <param name="TimeSeconds">Seconds from the start of the run.</param>
    /// <param name="Check">Which check.</param>
    /// <param name="Joint">Motor or module concerned.</param>
    /// <param name="Measured">The value measured.</param>
    /// <param name="Limit">The limit crossed.</param>
    /// <param name="Unit">Unit of both.</param>
    /// <param name="Action">The safe state taken.</param>
    /// <param name="Soft">A soft trip: back to PEDAL_UP, not E_STOP.</param>
    public sealed record TripEntry(double TimeSeconds, SafetyCheck Check, string Joint, double Measured, double Limit, string Unit, SafeState Action, bool Soft = false);
}
