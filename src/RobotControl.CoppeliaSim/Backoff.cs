namespace RobotControl.CoppeliaSim;

/// <summary>Reconnection back-off: the delay doubles after every failed attempt, from <see cref="Initial"/> up to <see cref="Maximum"/>, and resets on success.</summary>
public sealed class Backoff
{
    private TimeSpan _next;

    /// <summary>Creates the schedule.</summary>
    public Backoff(TimeSpan initial, TimeSpan maximum)
    {
        ArgumentOutOfRangeException.ThrowIfLessThanOrEqual(initial, TimeSpan.Zero);
        ArgumentOutOfRangeException.ThrowIfLessThan(maximum, initial);
        Initial = initial;
        Maximum = maximum;
        _next = initial;
    }

    /// <summary>First delay.</summary>
    public TimeSpan Initial { get; }

    /// <summary>Longest delay.</summary>
    public TimeSpan Maximum { get; }

    /// <summary>The delay before the next attempt; doubles the one after it.</summary>
    public TimeSpan NextDelay()
    {
        var delay = _next;
        _next = TimeSpan.FromTicks(Math.Min(Maximum.Ticks, _next.Ticks * 2));
        return delay;
    }

    /// <summary>An attempt succeeded: the next failure waits <see cref="Initial"/> again.</summary>
    public void Reset() => _next = Initial;
}
