using System.Runtime.InteropServices;

namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// Ctrl+C (SIGINT) and SIGTERM during a run: the first asks the run to stop (loop stopped, motors off, report
/// written, marked interrupted); a second one forces the exit at once.
/// </summary>
internal sealed class StopSignals : IDisposable
{
    private readonly CancellationTokenSource _stop = new();
    private readonly PosixSignalRegistration[] _registrations;
    private readonly TextWriter _error;
    private readonly string _stopping;
    private int _received;

    /// <summary>
    /// Takes over SIGINT and SIGTERM until disposed; messages go to <paramref name="error"/>, the first signal's says
    /// <paramref name="stopping"/> (what the stop does).
    /// </summary>
    public StopSignals(TextWriter error, string stopping = "loop off, motors off, report marked interrupted")
    {
        _error = error;
        _stopping = stopping;
        _registrations = [PosixSignalRegistration.Create(PosixSignal.SIGINT, Handle), PosixSignalRegistration.Create(PosixSignal.SIGTERM, Handle)];
    }

    /// <summary>Cancelled by the first signal.</summary>
    public CancellationToken Token => _stop.Token;

    /// <inheritdoc />
    public void Dispose()
    {
        foreach (var r in _registrations)
        {
            r.Dispose();
        }

        _stop.Dispose();
    }

    private void Handle(PosixSignalContext context)
    {
        if (Interlocked.Increment(ref _received) == 1)
        {
            context.Cancel = true; // handled here: stop cleanly
            _error.WriteLine($"{context.Signal}: stopping: {_stopping} (signal again to force the exit)");
            _stop.Cancel();
        }
        else
        {
            _error.WriteLine($"{context.Signal} again: forced exit, the motors are left to the modules' bus watchdogs");
            context.Cancel = false; // the default action: terminate now
        }
    }
}
