namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// One bring-up step (Commission or Calibrate pots) running on a thread of its own: its progress lines go to the
/// session's <see cref="ProgressLines"/>, its operator input comes from an <see cref="OperatorPrompt"/> (the page's
/// Continue), and <see cref="Stop"/> cancels it. The calibrator turns the motors off (read back) on a stop before it
/// ends; the step's last line (done, failed or stopped) is <see cref="Outcome"/>.
/// </summary>
public sealed class BringUpJob : IDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly TaskCompletionSource _ended = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly ProgressLines _lines;
    private volatile string _state = "running";
    private volatile string? _outcome;

    /// <summary>Starts <paramref name="run"/> (given the operator's input and the stop) as step <paramref name="step"/>.</summary>
    public BringUpJob(string step, ProgressLines lines, Action<OperatorPrompt, CancellationToken> run)
    {
        ArgumentNullException.ThrowIfNull(step);
        ArgumentNullException.ThrowIfNull(lines);
        ArgumentNullException.ThrowIfNull(run);
        Step = step;
        _lines = lines;
        Prompt = new OperatorPrompt(_stop.Token);
        var thread = new Thread(() => Body(run)) { IsBackground = true, Name = $"bring-up {step}" };
        thread.Start();
    }

    /// <summary>The step: <c>commission</c> or <c>calibrate</c>.</summary>
    public string Step { get; }

    /// <summary>The operator's input of the step.</summary>
    public OperatorPrompt Prompt { get; }

    /// <summary>running, waiting (for the operator's Continue), done, failed or stopped.</summary>
    public string State => _state == "running" && Prompt.Waiting ? "waiting" : _state;

    /// <summary>True until the step's thread has ended.</summary>
    public bool Running => !_ended.Task.IsCompleted;

    /// <summary>The step's last line once it has ended (what was done, or the failure naming the module or motor and what to do), else null.</summary>
    public string? Outcome => _outcome;

    /// <summary>True when the step ended in an exception its run does not handle (a calibration's motors then in doubt).</summary>
    public bool Unexpected { get; private set; }

    /// <summary>Completes when the step's thread has ended (after a stop: with the motors off, read back).</summary>
    public Task Ended => _ended.Task;

    /// <summary>Asks the step to stop, from any thread, never waiting.</summary>
    public void Stop()
    {
        try
        {
            _stop.Cancel();
        }
        catch (ObjectDisposedException)
        {
            // ended already
        }
    }

    /// <summary>Releases the stop's token source, once the step has ended.</summary>
    public void Dispose()
    {
        if (!Running)
        {
            _stop.Dispose();
        }
    }

    private void Body(Action<OperatorPrompt, CancellationToken> run)
    {
        try
        {
            run(Prompt, _stop.Token);
            _outcome = _lines.Last ?? $"{Step}: done";
            _state = "done";
        }
#pragma warning disable CA1031 // a step's thread ends in one line whatever it met: the page says it, the process stays
        catch (Exception ex)
#pragma warning restore CA1031
        {
            _outcome = ex switch
            {
                OperationCanceledException => $"{Step}: stopped",
                IOException or ArgumentException or UnauthorizedAccessException => ex.Message,
                _ => $"{Step}: failed ({ex.GetType().Name}: {ex.Message}); check the module's power and the bus, then run it again",
            };
            Unexpected = ex is not (OperationCanceledException or IOException or ArgumentException or UnauthorizedAccessException);
            _state = _stop.IsCancellationRequested ? "stopped" : "failed";
            _lines.WriteLine(_outcome);
        }
        finally
        {
            _ended.TrySetResult();
        }
    }
}
