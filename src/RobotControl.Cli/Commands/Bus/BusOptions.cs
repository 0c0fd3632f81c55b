using System.CommandLine;
using RobotControl.Bus.Client;
using RobotControl.Host.Session;
using RobotControl.Cli.Options;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>
/// The transport argument and the options every bus command shares, added to one command; <see cref="Run"/> opens the
/// session they describe.
/// </summary>
internal sealed class BusOptions
{
    private readonly Argument<string> _transport = new("transport")
    {
        Description = "serial:/dev/ttyUSB0?baud=1000000 | usb:0403:6001:<serial> | tcp:host:port | virtual:hardware/robots/lb-1.0.json",
    };

    private readonly Option<FileInfo?> _robot = new("--robot")
    {
        Description = "Robot data file (needed on a real bus; a virtual: transport names its own)",
    };

    private readonly Option<double> _marginMs = CliOption.Number("--margin-ms", "Reply timeout beyond the wire time, ms (USB adapters: their latency timer + 1)", 0.0, 1000.0, 3.0);

    /// <summary>Adds the transport argument, <c>--robot</c> and <c>--margin-ms</c> to <paramref name="command"/>.</summary>
    public BusOptions(Command command)
    {
        ArgumentNullException.ThrowIfNull(command);
        command.Arguments.Add(_transport);
        command.Options.Add(_robot);
        command.Options.Add(_marginMs);
        _transport.Validators.Add(result =>
        {
            // Checked while parsing: a malformed transport is refused before any device is opened.
            var text = result.Tokens.Count > 0 ? result.Tokens[0].Value : string.Empty;
            try
            {
                RobotConnection.CheckTransport(text);
            }
            catch (FormatException ex)
            {
                result.AddError(ex.Message);
            }
        });
    }

    /// <summary>
    /// Runs <paramref name="body"/> with a session on the parsed transport, turning expected failures (bad transport,
    /// I/O, bad robot file, refused operation) into a message on the error stream and exit code 2.
    /// </summary>
    public int Run(ParseResult parse, Func<RobotConnection, int> body)
    {
        ArgumentNullException.ThrowIfNull(body);
        return Guard(parse, () =>
        {
            var line = Line(parse);
            using var session = RobotConnection.Open(parse.GetValue(_transport)!, line.RobotFile, line.Options);
            return body(session);
        });
    }

    /// <summary>The parsed transport, robot file and client timing, re-openable at another baud.</summary>
    public BusLine Line(ParseResult parse)
    {
        ArgumentNullException.ThrowIfNull(parse);
        var margin = TimeSpan.FromMilliseconds(parse.GetValue(_marginMs));
        return new BusLine(parse.GetValue(_transport)!, parse.GetValue(_robot)?.FullName, new BusClientOptions { ResponseMargin = margin });
    }

    /// <summary>Runs <paramref name="body"/>, turning the expected failures into one line on the error stream and exit code 2.</summary>
    public static int Guard(ParseResult parse, Func<int> body)
    {
        ArgumentNullException.ThrowIfNull(parse);
        ArgumentNullException.ThrowIfNull(body);
        try
        {
            return body();
        }
        catch (Exception ex) when (ex is FormatException or IOException or ArgumentException or KeyNotFoundException or Definitions.Loading.RobotDataException or InvalidOperationException)
        {
            parse.InvocationConfiguration.Error.WriteLine(ex.Message);
            return 2;
        }
    }
}
