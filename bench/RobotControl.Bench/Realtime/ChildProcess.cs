using System.Diagnostics;

namespace RobotControl.Bench.Realtime;

/// <summary>A child process of the benchmark (the virtual robot behind its pty, or a CPU load), killed on dispose.</summary>
internal sealed class ChildProcess : IDisposable
{
    private readonly Process _process;

    private ChildProcess(Process process) => _process = process;

    /// <summary>
    /// Starts <c>robotctl bus-sim <paramref name="robot"/> --pty</c> (the built CLI of this repository) in its own
    /// process and returns it with the transport it prints. With <paramref name="fifoPriority"/> &gt; 0 it runs under
    /// <c>chrt -f</c> at that SCHED_FIFO priority: the simulator stands for module hardware, which host load does not slow.
    /// With <paramref name="baud"/> its modules are commissioned at that rate instead of the robot file's.
    /// </summary>
    public static (ChildProcess Sim, string Transport) StartBusSim(string robot, int fifoPriority, int? baud)
    {
        var cli = Path.GetFullPath(Path.Combine("src", "RobotControl.Cli", "bin", "Release", "net10.0", "robotctl.dll"));
        if (!File.Exists(cli))
        {
            throw new FileNotFoundException($"{cli}: build the CLI first (dotnet build src/RobotControl.Cli -c Release)");
        }

        var start = new ProcessStartInfo(fifoPriority > 0 ? "chrt" : "dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        string[] prefix = fifoPriority > 0 ? ["-f", fifoPriority.ToString(System.Globalization.CultureInfo.InvariantCulture), "dotnet"] : [];
        string[] rate = baud is { } b ? ["--baud", b.ToString(System.Globalization.CultureInfo.InvariantCulture)] : [];
        foreach (var a in prefix.Concat([cli, "bus-sim", robot, "--pty", .. rate]))
        {
            start.ArgumentList.Add(a);
        }

        var process = Process.Start(start) ?? throw new InvalidOperationException("bus-sim did not start");
        var child = new ChildProcess(process);
        var line = process.StandardOutput.ReadLine() ?? throw new InvalidOperationException($"bus-sim ended: {process.StandardError.ReadToEnd()}");
        var at = line.IndexOf("serial:", StringComparison.Ordinal);
        return at < 0 ? throw new InvalidOperationException($"bus-sim said '{line}'") : (child, line[at..].Trim());
    }

    /// <summary>Starts <c>stress-ng --cpu 1</c> (one core kept busy), or null with a reason when it is not installed.</summary>
    public static ChildProcess? StartCpuLoad(TimeSpan duration, out string? problem)
    {
        problem = null;
        try
        {
            var start = new ProcessStartInfo("stress-ng") { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (var a in new[] { "--cpu", "1", "--timeout", $"{(int)Math.Ceiling(duration.TotalSeconds)}s", "--quiet" })
            {
                start.ArgumentList.Add(a);
            }

            return new ChildProcess(Process.Start(start)!);
        }
        catch (System.ComponentModel.Win32Exception ex)
        {
            problem = ex.NativeErrorCode == 2 ? "stress-ng is not installed (apt-get install stress-ng)" : $"stress-ng did not start (error {ex.NativeErrorCode})";
            return null;
        }
    }

    /// <summary>
    /// Asks the process to end (SIGTERM: <c>bus-sim</c> stops serving and prints how it went) and returns the last line
    /// it printed, or null when it had to be killed.
    /// </summary>
    public string? Stop(TimeSpan patience)
    {
        if (_process.HasExited)
        {
            return null;
        }

        using (var kill = Process.Start("kill", ["-TERM", _process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]))
        {
            kill.WaitForExit();
        }

        if (!_process.WaitForExit(patience))
        {
            return null;
        }

        return _process.StandardOutput.ReadToEnd().Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries).LastOrDefault();
    }

    public void Dispose()
    {
        if (!_process.HasExited)
        {
            _process.Kill(entireProcessTree: true);
            _process.WaitForExit(5000);
        }

        _process.Dispose();
    }
}
