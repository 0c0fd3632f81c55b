using RobotControl.Robot.Bus;

namespace RobotControl.WebConsole.Session;

/// <summary>
/// The console's commands, handed from the web threads to the robot's one slot for work between bus cycles
/// (<see cref="BetweenCycles"/>): <see cref="Submit"/> queues a command and returns a task completed when the bus's
/// owner has run it; an exception it throws becomes a failed result with its message. The web threads never touch the
/// bus. An emergency stop is not a command: it goes to the safety supervisor directly and never waits here.
/// </summary>
public sealed class CommandQueue(BetweenCycles slot)
{
    private volatile bool _closed;

    /// <summary>Queues <paramref name="work"/>; the task completes when the bus's owner has run it.</summary>
    public Task<CommandResult> Submit(Func<CommandResult> work)
    {
        ArgumentNullException.ThrowIfNull(work);
        if (_closed)
        {
            return Task.FromResult(CommandResult.Fail(CommandOutcome.Failed, "the session is stopping"));
        }

        return slot.Post("console command", work).ContinueWith(
            static t => t.IsCompletedSuccessfully ? t.Result : CommandResult.Fail(CommandOutcome.Failed, Reason(t.Exception!)),
            CancellationToken.None,
            TaskContinuationOptions.ExecuteSynchronously,
            TaskScheduler.Default);
    }

    /// <summary>Refuses further commands (the session is stopping; queued ones fail when the bus cycles stop).</summary>
    public void Close() => _closed = true;

    private static string Reason(AggregateException ex) => ex.InnerException switch
    {
        InvalidOperationException or IOException or ArgumentException or KeyNotFoundException or OperationCanceledException => ex.InnerException.Message,
        { } other => $"{other.GetType().Name}: {other.Message}",
        null => ex.Message,
    };
}
