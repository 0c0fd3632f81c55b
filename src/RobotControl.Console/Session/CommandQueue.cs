using System.Collections.Concurrent;

namespace RobotControl.WebConsole.Session;

/// <summary>
/// Commands handed from the web threads to the thread that owns the bus: <see cref="Submit"/> queues work and returns
/// a task; the owner calls <see cref="Drain"/> between bus cycles, which runs the queued work on its own thread and
/// completes the tasks. The web threads never touch the bus.
/// </summary>
public sealed class CommandQueue
{
    private readonly ConcurrentQueue<(Func<CommandResult> Work, TaskCompletionSource<CommandResult> Done)> _queue = new();
    private volatile bool _closed;

    /// <summary>Queues <paramref name="work"/>; the task completes when the owner has run it.</summary>
    public Task<CommandResult> Submit(Func<CommandResult> work)
    {
        ArgumentNullException.ThrowIfNull(work);
        if (_closed)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.Failed, "the session is stopping"));
        }

        var done = new TaskCompletionSource<CommandResult>(TaskCreationOptions.RunContinuationsAsynchronously);
        _queue.Enqueue((work, done));
        return done.Task;
    }

    /// <summary>Runs every queued command (owner thread). Returns how many ran.</summary>
    public int Drain()
    {
        var n = 0;
        while (_queue.TryDequeue(out var item))
        {
            n++;
            try
            {
                item.Done.SetResult(item.Work());
            }
            catch (Exception ex) when (ex is IOException or InvalidOperationException or ArgumentException or KeyNotFoundException)
            {
                item.Done.SetResult(CommandResult.Fail(CommandOutcome.Failed, ex.Message));
            }
        }

        return n;
    }

    /// <summary>Refuses further commands and fails the queued ones (the owner is stopping).</summary>
    public void Close()
    {
        _closed = true;
        while (_queue.TryDequeue(out var item))
        {
            item.Done.SetResult(CommandResult.Fail(CommandOutcome.Failed, "the session stopped"));
        }
    }
}
