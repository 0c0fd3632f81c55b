namespace RobotControl.WebConsole.Session;

/// <summary>The session's event log: numbered entries, the last <see cref="Capacity"/> kept. Thread-safe.</summary>
public sealed class EventLog
{
    private readonly Lock _lock = new();
    private readonly Queue<EventEntry> _entries = new();
    private long _sequence;

    /// <summary>Entries kept.</summary>
    public int Capacity { get; init; } = 1000;

    /// <summary>Adds an entry.</summary>
    public void Add(double timeSeconds, string source, string message)
    {
        lock (_lock)
        {
            _entries.Enqueue(new EventEntry(++_sequence, timeSeconds, source, message));
            while (_entries.Count > Capacity)
            {
                _entries.Dequeue();
            }
        }
    }

    /// <summary>Entries numbered above <paramref name="after"/>, oldest first.</summary>
    public IReadOnlyList<EventEntry> After(long after)
    {
        lock (_lock)
        {
            return _entries.Where(e => e.Sequence > after).ToList();
        }
    }
}
