using RobotControl.Cli.Commands.Run;
using RobotControl.WebConsole.Replay;
using RobotControl.WebConsole.Server;

namespace RobotControl.Cli.Commands.WebConsole;

/// <summary>
/// <c>robotctl console --replay &lt;file.mcap&gt;</c>: the console's pages served from a recording, no robot
/// (<see cref="ReplaySession"/>), until Ctrl+C or SIGTERM. A file that is not a recording is one line and exit 2; a
/// file cut short is said in one line and played up to its last complete chunk.
/// </summary>
internal static class ConsoleReplay
{
    /// <summary>How often the playback clock moves the plots' ring.</summary>
    private static readonly TimeSpan PumpEvery = TimeSpan.FromMilliseconds(20);

    /// <summary>Serves <paramref name="path"/>; returns the exit code.</summary>
    public static int Run(string path, bool noGraph, ConsoleAccess access, TextWriter output, TextWriter error)
    {
        if (!noGraph)
        {
            error.WriteLine("console: give a graph file or --replay, not both");
            return 2;
        }

        if (!File.Exists(path))
        {
            error.WriteLine($"--replay {path}: no such file");
            return 2;
        }

        ConsoleServerOptions serving;
        ReplaySession replay;
        try
        {
            serving = access.Options();
        }
        catch (FormatException ex)
        {
            error.WriteLine(ex.Message);
            return 2;
        }

        try
        {
            replay = new ReplaySession(path, TimeProvider.System, PumpEvery);
        }
        catch (InvalidDataException ex)
        {
            error.WriteLine($"--replay {ex.Message}");
            return 2;
        }

        using (replay)
        {
            if (replay.Truncated is { } truncated)
            {
                error.WriteLine(truncated);
            }

            ConsoleServer server;
            try
            {
                server = ConsoleServer.StartAsync(replay, serving).GetAwaiter().GetResult();
            }
            catch (Exception ex) when (ex is IOException or FormatException)
            {
                error.WriteLine($"console: cannot serve on {serving.Bind}: {ex.Message}");
                return 2;
            }

            output.WriteLine($"console: replay of {Path.GetFileName(path)} ({replay.DurationSeconds:F1} s), {replay.Status.Robot}, graph {replay.Status.Graph}");
            output.WriteLine($"console: {server.OpenUrl}");
            output.WriteLine("console: Ctrl+C stops");
            using var signals = new StopSignals(error, "pages closed");
            signals.Token.WaitHandle.WaitOne();
            replay.Close();
            ConsoleCommand.CloseServer(server, error);
        }

        return 0;
    }
}
