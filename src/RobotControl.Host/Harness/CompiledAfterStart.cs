using System.Globalization;
using System.Text.Json;

namespace RobotControl.Host.Harness;

/// <summary>
/// What the JIT compiled on the real-time threads once they were running: on the loop thread after its first tick, on
/// the bus thread after its first cycle. The cycle's code is compiled before arming; what is left here is paths first
/// taken later (a status poll, a fault, a setting changed) and should stay near zero.
/// </summary>
/// <param name="LoopMethods">Methods compiled on the loop thread after its first tick.</param>
/// <param name="LoopTime">Time the loop thread spent compiling them.</param>
/// <param name="BusMethods">Methods compiled on the bus thread after its first cycle.</param>
/// <param name="BusTime">Time the bus thread spent compiling them.</param>
public sealed record CompiledAfterStart(long LoopMethods, TimeSpan LoopTime, long BusMethods, TimeSpan BusTime)
{
    /// <summary>One line, e.g. "loop thread 1 method (0.03 ms), bus thread 14 methods (1.15 ms)".</summary>
    public string Summary => string.Create(
        CultureInfo.InvariantCulture,
        $"loop thread {LoopMethods} {Methods(LoopMethods)} ({LoopTime.TotalMilliseconds:F2} ms), bus thread {BusMethods} {Methods(BusMethods)} ({BusTime.TotalMilliseconds:F2} ms)");

    /// <summary>Writes <c>"compiled_after_start": {"loop_thread": {"methods", "ms"}, "bus_thread": {...}}</c>.</summary>
    public void Write(Utf8JsonWriter writer)
    {
        ArgumentNullException.ThrowIfNull(writer);
        writer.WriteStartObject("compiled_after_start");
        Thread(writer, "loop_thread", LoopMethods, LoopTime);
        Thread(writer, "bus_thread", BusMethods, BusTime);
        writer.WriteEndObject();
    }

    private static string Methods(long n) => n == 1 ? "method" : "methods";

    private static void Thread(Utf8JsonWriter writer, string name, long methods, TimeSpan time)
    {
        writer.WriteStartObject(name);
        writer.WriteNumber("methods", methods);
        writer.WriteNumber("ms", Math.Round(time.TotalMilliseconds, 3));
        writer.WriteEndObject();
    }
}
