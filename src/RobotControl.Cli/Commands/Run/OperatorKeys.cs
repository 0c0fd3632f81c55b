namespace RobotControl.Cli.Commands.Run;

/// <summary>
/// The command line's E-STOP during a run: a line <c>e</c> (or <c>estop</c>) on the standard input, typed at the terminal
/// (e, Enter) or written to a pipe. It asks the safety supervisor for an operator emergency stop (hold, E_STOP; the run goes on
/// holding); Ctrl+C remains the way to end the run with the motors off. Read on a background thread that never touches the
/// loop: the request is taken in the next bus cycle. It reads the raw standard input stream, not <see cref="Console.In"/>
/// (a synchronised reader shared with the rest of the process) or <see cref="Console.ReadKey(bool)"/> (which would
/// switch the terminal's modes under the progress display).
/// </summary>
internal sealed class OperatorKeys : IDisposable
{
    /// <summary>What the run prints so the operator knows the keys.</summary>
    public const string Help = "E-STOP: type e and Enter (from a pipe: a line 'estop'): the arms hold; Ctrl+C ends the run with the motors off";

    private readonly CancellationTokenSource _emergencyStop = new();
    private readonly TextWriter _error;
    private readonly TextReader _input;

    private OperatorKeys(TextReader input, TextWriter error)
    {
        _input = input;
        _error = error;
        var reader = new Thread(Read) { IsBackground = true, Name = "operator keys" };
        reader.Start();
    }

    /// <summary>Cancelled when the operator asks for an emergency stop.</summary>
    public CancellationToken EmergencyStop => _emergencyStop.Token;

    /// <summary>Listens on the process's standard input stream, line by line.</summary>
    public static OperatorKeys FromConsole(TextWriter error) =>
        new(new StreamReader(Console.OpenStandardInput(), System.Text.Encoding.UTF8, detectEncodingFromByteOrderMarks: false), error);

    /// <inheritdoc />
    public void Dispose() => _emergencyStop.Dispose(); // the reader thread is a background thread, blocked on input

    /// <summary>True when <paramref name="line"/> asks for an emergency stop.</summary>
    internal static bool IsEmergencyStop(string line) => line.Trim().ToLowerInvariant() is "e" or "estop" or "e-stop";

    private void Read()
    {
        try
        {
            while (!_emergencyStop.IsCancellationRequested)
            {
                var line = _input.ReadLine();
                if (line is null)
                {
                    return; // end of input: no operator at this pipe
                }

                if (IsEmergencyStop(line))
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
