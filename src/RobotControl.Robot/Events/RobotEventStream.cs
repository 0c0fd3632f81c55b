namespace RobotControl.Robot.Events;

/// <summary>
/// The robot's one event stream: the bus thread publishes (<see cref="Publish"/>), and every consumer (the run's
/// harness, the console, the command line, a test) reads its own copy through a subscription, so that no consumer
/// takes events away from another. A subscription made with <c>fromStart</c> first sees what was published before it
/// (the last <see cref="HistoryLimit"/> events). Events are rare (set-up, faults); a reader that falls more than
/// <see cref="HistoryLimit"/> behind loses the oldest and is told how many (<see cref="RobotEventSubscription.Dropped"/>).
/// </summary>
public sealed class RobotEventStream
{
    /// <summary>Events kept for late subscribers, and unread events kept per subscription.</summary>
    public const int HistoryLimit = 10_000;

    private readonly Lock _gate = new();
    private readonly Queue<RobotEvent> _history = new();
    private RobotEventSubscription[] _subscriptions = [];
    private long _published;

    /// <summary>Events published so far.</summary>
    public long Published => Interlocked.Read(ref _published);

    /// <summary>Publishes <paramref name="e"/> to every subscription (the bus thread).</summary>
    public void Publish(RobotEvent e)
    {
        ArgumentNullException.ThrowIfNull(e);
        RobotEventSubscription[] subscriptions;
        lock (_gate)
        {
            _history.Enqueue(e);
            if (_history.Count > HistoryLimit)
            {
                _history.Dequeue();
            }

            subscriptions = _subscriptions;
            _published++;
        }

        foreach (var s in subscriptions)
        {
            s.Add(e);
        }
    }

    /// <summary>A new reader of the stream; with <paramref name="fromStart"/>, the events published so far come first.</summary>
    public RobotEventSubscription Subscribe(bool fromStart = false)
    {
        lock (_gate)
        {
            var subscription = new RobotEventSubscription(this, fromStart ? [.. _history] : []);
            _subscriptions = [.. _subscriptions, subscription];
            return subscription;
        }
    }

    /// <summary>Every event kept so far, oldest first (a copy).</summary>
    public IReadOnlyList<RobotEvent> History()
    {
        lock (_gate)
        {
            return [.. _history];
        }
    }

    internal void Remove(RobotEventSubscription subscription)
    {
        lock (_gate)
        {
            _subscriptions = [.. _subscriptions.Where(s => !ReferenceEquals(s, subscription))];
        }
    }
}

/// <summary>One consumer's reading of a <see cref="RobotEventStream"/>: its events in order, read by one thread.</summary>
public sealed class RobotEventSubscription : IDisposable
{
    private readonly RobotEventStream _stream;
    private readonly System.Collections.Concurrent.ConcurrentQueue<RobotEvent> _unread;
    private long _dropped;

    internal RobotEventSubscription(RobotEventStream stream, IEnumerable<RobotEvent> backlog)
    {
        _stream = stream;
        _unread = new(backlog);
    }

    /// <summary>Events this reader lost because it fell more than <see cref="RobotEventStream.HistoryLimit"/> behind.</summary>
    public long Dropped => Interlocked.Read(ref _dropped);

    /// <summary>The next unread event, oldest first.</summary>
    public bool TryRead(out RobotEvent e)
    {
        if (_unread.TryDequeue(out var next))
        {
            e = next;
            return true;
        }

        e = null!;
        return false;
    }

    /// <summary>Every unread event, oldest first.</summary>
    public IReadOnlyList<RobotEvent> ReadAll()
    {
        var list = new List<RobotEvent>();
        while (_unread.TryDequeue(out var e))
        {
            list.Add(e);
        }

        return list;
    }

    /// <summary>Stops receiving events.</summary>
    public void Dispose() => _stream.Remove(this);

    internal void Add(RobotEvent e)
    {
        _unread.Enqueue(e);
        if (_unread.Count > RobotEventStream.HistoryLimit && _unread.TryDequeue(out _))
        {
            Interlocked.Increment(ref _dropped);
        }
    }
}
