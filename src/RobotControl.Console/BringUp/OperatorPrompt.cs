namespace RobotControl.WebConsole.BringUp;

/// <summary>
/// The operator's input of a bring-up step on the console: where the CLI reads a line from its terminal (connect the
/// next module, put the arm in its fixture pose, then press Enter), <see cref="ReadLine"/> waits for the page's
/// Continue (<see cref="Continue"/>) and the page shows the step's last line as the instruction. A stop ends the wait
/// at once with no input (null), which the step reports as stopped.
/// </summary>
public sealed class OperatorPrompt(CancellationToken stop) : TextReader
{
    private readonly SemaphoreSlim _continued = new(0, 1);
    private volatile bool _waiting;

    /// <summary>True while the step waits for the operator.</summary>
    public bool Waiting => _waiting;

    /// <summary>The page's Continue: lets a waiting step go on. False when the step is not waiting.</summary>
    public bool Continue()
    {
        if (!_waiting)
        {
            return false;
        }

        try
        {
            _continued.Release();
        }
        catch (SemaphoreFullException)
        {
            // pressed twice: once is enough
        }

        return true;
    }

    /// <inheritdoc />
    public override string? ReadLine()
    {
        _waiting = true;
        try
        {
            _continued.Wait(stop);
            return string.Empty;
        }
        catch (OperationCanceledException)
        {
            return null;
        }
        finally
        {
            _waiting = false;
        }
    }
}
