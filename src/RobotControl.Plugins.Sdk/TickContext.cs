namespace RobotControl.Plugins.Sdk;

/// <summary>
/// What a plug-in knows about the current tick. Times come from the loop's <see cref="TimeProvider"/> (virtual in
/// tests and simulation), never from the wall clock.
/// </summary>
/// <param name="Index">Tick number since the loop started (0 for the first tick).</param>
/// <param name="Timestamp">The loop clock's timestamp at the tick (in <see cref="TimeProvider.TimestampFrequency"/> units).</param>
/// <param name="Elapsed">Loop-clock time since the first tick.</param>
/// <param name="Period">The loop's nominal period.</param>
public readonly record struct TickContext(long Index, long Timestamp, TimeSpan Elapsed, TimeSpan Period)
{
    /// <summary>Seconds since the first tick.</summary>
    public double TimeSeconds => Elapsed.Ticks / (double)TimeSpan.TicksPerSecond;

    /// <summary>The nominal period in seconds (the integration step).</summary>
    public double PeriodSeconds => Period.Ticks / (double)TimeSpan.TicksPerSecond;
}
