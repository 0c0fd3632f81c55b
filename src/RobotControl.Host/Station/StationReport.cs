using System.Globalization;
using System.Text;
using System.Text.Json;
using RobotControl.Runtime.GraphFiles;
using RobotControl.Runtime.Loop;

namespace RobotControl.Host.Station;

/// <summary>What a station run (<see cref="StationRun"/>) did: its loop, its plug-ins' faults, and every output signal's last value (the links' counters among them).</summary>
/// <param name="Graph">The graph file's name.</param>
/// <param name="DurationSeconds">Wall-clock time the loop ran.</param>
/// <param name="Ticks">Ticks run.</param>
/// <param name="DeadlineMisses">Ticks started late.</param>
/// <param name="TickMedianUs">Median tick time.</param>
/// <param name="TickP99Us">99th-percentile tick time.</param>
/// <param name="TickMaxUs">Longest tick.</param>
/// <param name="Interrupted">True when a stop request (Ctrl+C, SIGTERM) ended it early.</param>
/// <param name="LoopStopped">False when the loop's thread was still in a tick when the run ended (a plug-in that does not return).</param>
/// <param name="Scheduling">The threads' scheduling as applied.</param>
/// <param name="PluginFaults">Each plug-in fault: the instance, loop time and message.</param>
/// <param name="Signals">Every output signal's value at the end, by name.</param>
public sealed record StationReport(
    string Graph,
    double DurationSeconds,
    long Ticks,
    long DeadlineMisses,
    double TickMedianUs,
    double TickP99Us,
    double TickMaxUs,
    bool Interrupted,
    bool LoopStopped,
    string Scheduling,
    IReadOnlyList<(string Instance, double TimeSeconds, string Message)> PluginFaults,
    IReadOnlyDictionary<string, double> Signals)
{
    /// <summary>Exit code of an interrupted run (128 + SIGINT, as shells report it).</summary>
    public const int InterruptedExitCode = 130;

    /// <summary>0: clean; 130: interrupted; 1: plug-in faults, deadline misses, or a loop left in a tick.</summary>
    public int ExitCode => Interrupted ? InterruptedExitCode : PluginFaults.Count == 0 && DeadlineMisses == 0 && LoopStopped ? 0 : 1;

    /// <summary>The report of <paramref name="loaded"/>'s run on <paramref name="loop"/>.</summary>
    internal static StationReport Of(LoadedGraph loaded, ControlLoop loop, TimeSpan elapsed, bool interrupted, bool stopped, string scheduling)
    {
        var outputs = loaded.Program.OutputSignals;
        var values = outputs.Values;
        var signals = new SortedDictionary<string, double>(StringComparer.Ordinal);
        for (var i = 0; i < outputs.Names.Count; i++)
        {
            signals[outputs.Names[i]] = values[i];
        }

        var s = loop.Statistics;
        return new StationReport(
            Path.GetFileName(loaded.Path),
            elapsed.TotalSeconds,
            loop.TickCount,
            s.DeadlineMisses,
            s.MedianUs,
            s.P99Us,
            s.MaxUs,
            interrupted,
            stopped,
            scheduling,
            [.. loaded.Program.Faults.Select(f => (f.Instance, f.Time.TotalSeconds, f.Message))],
            signals);
    }

    /// <summary>The summary lines <c>robotctl run</c> prints.</summary>
    public IEnumerable<string> Lines()
    {
        var c = CultureInfo.InvariantCulture;
        yield return string.Create(c, $"summary: station without a robot, {Ticks} ticks in {DurationSeconds:F3} s (wall clock), {DeadlineMisses} deadline misses (ticks started late)");
        yield return string.Create(c, $"  tick time (us): median {TickMedianUs:F1}, p99 {TickP99Us:F1}, max {TickMaxUs:F1}");
        yield return $"  threads: {Scheduling}";
        yield return string.Create(c, $"  plug-in faults: {PluginFaults.Count}");
        foreach (var (instance, time, message) in PluginFaults.Take(20))
        {
            yield return string.Create(c, $"    {time,8:F3} s  {instance}: {message}");
        }

        if (!LoopStopped)
        {
            yield return "  the loop was still in a tick when the run ended: a plug-in's tick did not return";
        }
    }

    /// <summary>The report as JSON (the file <c>--report</c> writes).</summary>
    public string ToJson()
    {
        using var stream = new MemoryStream();
        using (var w = new Utf8JsonWriter(stream, new JsonWriterOptions { Indented = true }))
        {
            w.WriteStartObject();
            w.WriteString("kind", "station");
            w.WriteString("graph", Graph);
            Harness.RunReport.WriteLoop(w, DurationSeconds, Ticks, DeadlineMisses, TickMedianUs, TickP99Us, TickMaxUs);
            w.WriteBoolean("interrupted", Interrupted);
            w.WriteBoolean("loop_stopped", LoopStopped);
            w.WriteString("threads", Scheduling);
            w.WriteStartArray("plugin_faults");
            foreach (var (instance, time, message) in PluginFaults)
            {
                w.WriteStartObject();
                w.WriteString("instance", instance);
                w.WriteNumber("time_s", Math.Round(time, 6));
                w.WriteString("message", message);
                w.WriteEndObject();
            }

            w.WriteEndArray();
            w.WriteStartObject("signals");
            foreach (var (name, value) in Signals)
            {
                if (double.IsFinite(value))
                {
                    w.WriteNumber(name, value);
                }
                else
                {
                    w.WriteString(name, value.ToString(CultureInfo.InvariantCulture));
                }
            }

            w.WriteEndObject();
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(stream.ToArray());
    }
}
