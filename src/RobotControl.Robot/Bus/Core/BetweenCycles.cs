using System.Collections.Concurrent;
using RobotControl.Bus.Client;

namespace RobotControl.Robot.Bus;

/// <summary>
/// The one slot for work that must run on the thread that owns the bus: discovery, parameter reads and writes,
/// reboots, homing, the motors on or off, an operator's commands. While a thread owns the bus (the bus thread of a
/// wall-clock session, a virtual schedule, <see cref="BusRobot.RunFor"/>), work from other threads is queued
/// (<see cref="Post{T}"/>) and run there between two cycles, one piece per gap, so a cycle is never delayed by more
/// than one piece; the owner's own calls, and calls while nobody owns the bus, run at once. An emergency stop is not
/// work in this queue: it is a lock-free request to the goal writer, and while it is on its way to the wire the
/// piece of work running is cut short at its next transaction (<see cref="BusInterruption"/>) and no other starts.
/// </summary>
[WrittenBy(RobotThread.Bus)]
public sealed class BetweenCycles
{
    private readonly ConcurrentQueue<IWork> _queue = new();
    private readonly Lock _gate = new();
    private readonly BusClient _client;
    private volatile string? _linkFailure;
    private readonly BusInterruption _stop;
    private volatile Thread? _owner;
    private long _ran;

    internal BetweenCycles(BusClient client, BusInterruption stop)
    {
        _client = client;
        _stop = stop;
    }

    private interface IWork
    {
        void Run();

        void Fail(Exception ex);
    }

    /// <summary>Pieces of work waiting.</summary>
    public int Pending => _queue.Count;

    /// <summary>Pieces of work run so far.</summary>
    public long Ran => Interlocked.Read(ref _ran);

    /// <summary>True on the thread that owns the bus (false while nobody does).</summary>
    public bool IsOwner => _owner == Thread.CurrentThread;

    /// <summary>True on the thread that owns the bus, or on any thread while nobody does.</summary>
    public bool OnBusThread => _owner is not { } owner || owner == Thread.CurrentThread;

    /// <summary>
    /// Runs <paramref name="work"/> on the bus's owner and returns its result: at once on the owner or while nobody
    /// owns the bus, else between two cycles (the caller waits).
    /// </summary>
    /// <exception cref="BusWorkInterruptedException">An emergency stop cut the work short.</exception>
    public T Run<T>(string what, Func<T> work) => OnBusThread ? work() : Post(what, work).GetAwaiter().GetResult();

    /// <inheritdoc cref="Run{T}(string, Func{T})"/>
    public void Run(string what, Action work)
    {
        ArgumentNullException.ThrowIfNull(work);
        _ = Run(what, () =>
        {
            work();
            return true;
        });
    }

    /// <summary>Queues <paramref name="work"/> for the bus's owner; the task completes when it has run (at once while nobody owns the bus).</summary>
    public Task<T> Post<T>(string what, Func<T> work)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(what);
        ArgumentNullException.ThrowIfNull(work);
        var item = new Work<T>(work);
        lock (_gate)
        {
            if (_owner is not null)
            {
                if (_linkFailure is { } why)
                {
                    item.Fail(LinkFailed(why)); // refused at once: it would wait for a cycle that cannot run
                    return item.Done.Task;
                }

                _queue.Enqueue(item);
                return item.Done.Task;
            }
        }

        item.Run(); // nobody owns the bus: the caller does, for this piece
        return item.Done.Task;
    }

    /// <summary>Makes the calling thread the bus's owner until the result is disposed (pieces still queued then fail).</summary>
    /// <exception cref="InvalidOperationException">Another thread owns the bus.</exception>
    internal Ownership Own()
    {
        lock (_gate)
        {
            if (_owner is { } other && other != Thread.CurrentThread)
            {
                throw new InvalidOperationException($"the bus is owned by the thread \"{other.Name}\"; run cycles on one thread at a time");
            }

            var nested = _owner is not null;
            _owner = Thread.CurrentThread;
            return new Ownership(this, nested);
        }
    }

    /// <summary>
    /// The owner: the link failed this cycle (an adapter unplugged, the other end of a pty gone). Every queued piece
    /// fails with <paramref name="why"/> and new ones are refused at once until a cycle succeeds again
    /// (<see cref="LinkWorks"/>): a caller is told, never left waiting for a cycle that cannot run.
    /// </summary>
    internal void LinkFailedThisCycle(string why)
    {
        _linkFailure = why;
        while (_queue.TryDequeue(out var item))
        {
            item.Fail(LinkFailed(why));
        }
    }

    /// <summary>The owner: a cycle succeeded; pieces are queued again.</summary>
    internal void LinkWorks() => _linkFailure = null;

    private static IOException LinkFailed(string why) => new($"the bus link failed ({why}): nothing was sent");

    /// <summary>Runs the next piece of work, if any and no stop is on its way (the owner, between cycles).</summary>
    internal void RunNext()
    {
        if (_stop.IsRaised || !_queue.TryDequeue(out var item))
        {
            return;
        }

        _client.Interruption = _stop;
        try
        {
            item.Run();
        }
        finally
        {
            _client.Interruption = null;
            Interlocked.Increment(ref _ran);
        }
    }

    private void Release(bool nested)
    {
        if (nested)
        {
            return;
        }

        lock (_gate)
        {
            _owner = null;
        }

        while (_queue.TryDequeue(out var item))
        {
            item.Fail(new InvalidOperationException("the bus cycles stopped before this ran; nothing was sent"));
        }
    }

    /// <summary>The bus's ownership by one thread (see <see cref="Own"/>).</summary>
    internal readonly struct Ownership(BetweenCycles slot, bool nested) : IDisposable
    {
        public void Dispose() => slot.Release(nested);
    }

    private sealed class Work<T>(Func<T> work) : IWork
    {
        public TaskCompletionSource<T> Done { get; } = new(TaskCreationOptions.RunContinuationsAsynchronously);

        public void Run()
        {
            try
            {
                Done.SetResult(work());
            }
#pragma warning disable CA1031 // the piece's caller gets whatever it threw
            catch (Exception ex)
#pragma warning restore CA1031
            {
                Done.SetException(ex);
            }
        }

        public void Fail(Exception ex) => Done.TrySetException(ex);
    }
}
