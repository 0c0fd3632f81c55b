using RobotControl.Runtime.Graph;
using RobotControl.WebConsole.Session;

namespace RobotControl.WebConsole.Editor;

/// <summary>
/// Runs one graph file at a time behind the console's <see cref="SwitchableSession"/>. Stopping turns the motors off
/// through the session (the supervisor's motors-off, as any stop) and closes it; starting stops the current graph
/// first (one bus, one owner) and opens a session on the new file with the console's robot options (virtual robot or
/// configured transport). Starts and stops are applied one at a time.
/// </summary>
public sealed class GraphRunner : IDisposable
{
    private readonly SwitchableSession _session;
    private readonly Func<string, IConsoleSession> _open;
    private readonly SemaphoreSlim _gate = new(1, 1);
    private string? _problem;

    /// <summary>Runs graphs behind <paramref name="session"/>, whose current session runs <paramref name="graphPath"/>.</summary>
    /// <param name="session">The session the console serves.</param>
    /// <param name="graphPath">The graph file the current session runs.</param>
    /// <param name="transport">Where graphs run, for the page (e.g. <c>virtual robot</c>).</param>
    /// <param name="open">Opens a session on a graph file (throws as the session does when it cannot).</param>
    public GraphRunner(SwitchableSession session, string graphPath, string transport, Func<string, IConsoleSession> open)
    {
        ArgumentNullException.ThrowIfNull(session);
        ArgumentNullException.ThrowIfNull(open);
        _session = session;
        GraphPath = graphPath;
        Transport = transport;
        _open = open;
    }

    /// <summary>The graph file that runs (or ran last).</summary>
    public string? GraphPath { get; private set; }

    /// <summary>Where graphs run.</summary>
    public string Transport { get; }

    /// <summary>True while a graph runs.</summary>
    public bool Running => _session.Current is not StoppedSession;

    /// <summary>What runs now.</summary>
    public RunView View => new(Running, Running && GraphPath is not null ? Path.GetFileName(GraphPath) : null, Transport, _problem);

    /// <summary>Stops the running graph (motors off); a no-op when none runs.</summary>
    public async Task<RunView> StopAsync()
    {
        await _gate.WaitAsync().ConfigureAwait(false);
        try
        {
            await StopCurrentAsync().ConfigureAwait(false);
            _problem = null;
            return View;
        }
        finally
        {
            _gate.Release();
        }
    }

    /// <summary>Stops the running graph and starts <paramref name="graphPath"/>; on failure nothing runs and the view says why.</summary>
    public async Task<RunView> StartAsync(string graphPath)
    {
        ArgumentException.ThrowIfNullOrEmpty(graphPath);
        await _gate.WaitAsync().ConfigureAwait(false);
        try
        {
            await StopCurrentAsync().ConfigureAwait(false);
            GraphPath = graphPath;
            try
            {
                var next = await Task.Run(() => _open(graphPath)).ConfigureAwait(false);
                _session.Replace(next).Dispose();
                _problem = null;
            }
            catch (GraphException ex)
            {
                _problem = ex.Message;
            }
            catch (Exception ex) when (ex is InvalidOperationException or IOException or ArgumentException or FormatException or UnauthorizedAccessException)
            {
                _problem = $"{Path.GetFileName(graphPath)}: {ex.Message}";
            }

            return View;
        }
        finally
        {
            _gate.Release();
        }
    }

    /// <inheritdoc />
    public void Dispose() => _gate.Dispose();

    private async Task StopCurrentAsync()
    {
        var current = _session.Current;
        if (current is StoppedSession)
        {
            return;
        }

        // Motors off through the supervisor first (refused only while homing runs or at E_STOP, where they are off or
        // about to be); closing the session then switches off whatever is still on.
        await current.TorqueAsync(false).ConfigureAwait(false);
        var stopped = new StoppedSession(current);
        _session.Replace(stopped);
        stopped.Ended(await Task.Run(current.Close).ConfigureAwait(false));
        current.Dispose();
    }
}
