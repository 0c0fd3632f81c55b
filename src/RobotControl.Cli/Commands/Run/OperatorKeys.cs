namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// The command line's E-STOP during a run: on a terminal the key <c>e</c> (or the space bar), from a pipe a line
/// <c>estop</c> (or <c>e</c>). It asks the safety supervisor for an operator emergency stop (hold, E_STOP; the run goes on
/// holding); Ctrl+C remains the way to end the run with the motors off. Read on a background thread that never touches the
/// loop: the request is taken in the next bus cycle.
/// </summary>
internal sealed class OperatorKeys : IDisposable
{
    /// <summary>What the run prints so the operator knows the keys.</summary>
    public const string Help = "E-STOP: press e or space (from a pipe: a line 'estop'): the arms hold; Ctrl+C ends the run with the motors off";

    private readonly CancellationTokenSource _emergencyStop = new();
    private readonly TextWriter _error;
    private readonly TextReader _input;
    private readonly bool _keys;

    private OperatorKeys(TextReader input, bool keys, TextWriter error)
    {
        _input = input;
        _keys = keys;
        _error = error;
        var reader = new Thread(Read) { IsBackground = true, Name = "operator keys" };
        reader.Start();
    }

    /// <summary>Cancelled when the operator asks for an emergency stop.</summary>
    public CancellationToken EmergencyStop => _emergencyStop.Token;

    /// <summary>Listens on the process's standard input: single keys on a terminal, lines from a pipe or file.</summary>
    public static OperatorKeys FromConsole(TextWriter error) => new(Console.In, !Console.IsInputRedirected, error);

    /// <inheritdoc />
    public void Dispose() => _emergencyStop.Dispose();

    /// <summary>True when <paramref name="line"/> asks for an emergency stop.</summary>
    internal static bool IsEmergencyStop(string line) => line.Trim().ToLowerInvariant() is "e" or "estop" or "e-stop";

    private void Read()
    {
        try
        {
            while (!_emergencyStop.IsCancellationRequested)
            {
                bool stop;
                if (_keys)
                {
                    var key = Console.ReadKey(intercept: true);
                    stop = key.Key is ConsoleKey.E or ConsoleKey.Spacebar;
                }
                else
                {
                    var line = _input.ReadLine();
                    if (line is null)
                    {
                        return; // end of input: no operator at this pipe
                    }

                    stop = IsEmergencyStop(line);
                }

                if (stop)
                {
                    _error.WriteLine("E-STOP (command line): the arms hold at E_STOP; Ctrl+C ends the run with the motors off");
                    _emergencyStop.Cancel();
                }
            }
        }
        catch (Exception ex) when (ex is InvalidOperationException or IOException or ObjectDisposedException)
        {
            // no console to read (a service, a closed terminal): the keys are simply not there
        }
    }
}
