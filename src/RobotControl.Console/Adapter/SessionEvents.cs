using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Adapter;

/// <summary>
/// The live session's event log, each entry timed in seconds since the session began (the session layer's clock, so
/// virtual time on the virtual robot).
/// <para>Written by every thread of the session (the log is thread-safe); the clock and the start never change.</para>
/// </summary>
internal sealed class SessionEvents(TimeProvider clock)
{
    private readonly EventLog _log = new();
    private readonly long _begin = clock.GetTimestamp();

    /// <summary>Seconds since the session began.</summary>
    public double Now => SecondsAt(clock.GetTimestamp());

    /// <summary>Seconds from the session's start to <paramref name="timestamp"/> (a timestamp of the session's clock).</summary>
    public double SecondsAt(long timestamp) => clock.GetElapsedTime(_begin, timestamp).TotalSeconds;

    /// <summary>Adds an entry timed now.</summary>
    public void Add(string source, string message) => _log.Add(Now, source, message);

    /// <summary>Entries numbered above <paramref name="after"/>, oldest first.</summary>
    public IReadOnlyList<EventEntry> After(long after) => _log.After(after);
}
