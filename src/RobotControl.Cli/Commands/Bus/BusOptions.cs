using System.CommandLine;

namespace RobotControl.Cli.Commands.Bus;

/// <summary>Arguments and options the bus commands share.</summary>
internal static class BusOptions
{
    public static Argument<string> Transport() => new("transport")
    {
        Description = "serial:/dev/ttyUSB0?baud=1000000 | usb:0403:6001:<serial> | tcp:host:port | virtual:hardware/robots/lb-1.0.json",
    };

    public static Option<FileInfo?> Robot() => new("--robot")
    {
        Description = "Robot data file (needed on a real bus; a virtual: transport names its own)",
    };

    public static Option<double> MarginMs() => new("--margin-ms")
    {
        Description = "Reply timeout beyond the wire time, ms (USB adapters: their latency timer + 1)",
        DefaultValueFactory = _ => 3,
    };

    /// <summary>Runs <paramref name="body"/> with a session, turning expected failures into messages and exit codes.</summary>
    public static int Run(string transport, FileInfo? robot, double marginMs, TextWriter error, Func<BusSession, int> body)
    {
        try
        {
            using var session = BusSession.Open(transport, robot?.FullName, TimeSpan.FromMilliseconds(marginMs));
            return body(session);
        }
        catch (Exception ex) when (ex is FormatException or IOException or ArgumentException or KeyNotFoundException or Hardware.Loading.RobotDataException or InvalidOperationException)
        {
            error.WriteLine(ex.Message);
            return 2;
        }
    }
}
