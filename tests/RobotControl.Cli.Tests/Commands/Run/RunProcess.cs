using System.Diagnostics;
using System.Text;

namespace RobotControl.Cli.Tests.Commands.Run;

/// <summary>Runs <c>robotctl</c> as a child process (as a user would), with its output collected line by line.</summary>
internal sealed class RunProcess : IDisposable
{
    /// <summary>The test collection of every test that runs a robot in real time: one at a time, on a shared machine.</summary>
    public const string Collection = "real-time runs";

    /// <summary>How long a test waits for a child robotctl to say something or to exit, on a shared, loaded machine.</summary>
    public static readonly TimeSpan Patience = TimeSpan.FromSeconds(90);

    private readonly Process _process;
    private readonly StringBuilder _output = new();

    public RunProcess(params string[] args)
        : this(false, args)
    {
    }

    /// <summary>Starts <c>robotctl</c> with <paramref name="args"/>; with <paramref name="typing"/>, its standard input is a pipe for <see cref="Type"/>.</summary>
    public RunProcess(bool typing, params string[] args)
    {
        // robotctl runs as from an operator's terminal, where Ctrl+C reaches it. A test run started from a background
        // job of a script inherits SIGINT ignored (POSIX), and .NET keeps an inherited SIG_IGN for SIGINT, so the
        // child is exec'd through a one-line Python wrapper that restores the default first (a shell cannot: it may
        // not reset a signal ignored on entry). The process ID stays robotctl's.
        var start = new ProcessStartInfo("python3") { RedirectStandardInput = typing, RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
        start.ArgumentList.Add("-c");
        start.ArgumentList.Add("import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execvp(sys.argv[1], sys.argv[1:])");
        start.ArgumentList.Add("dotnet");
        start.ArgumentList.Add(Path.Combine(AppContext.BaseDirectory, "robotctl.dll"));
        foreach (var a in args)
        {
            start.ArgumentList.Add(a);
        }

        _process = new Process { StartInfo = start };
        _process.OutputDataReceived += (_, e) => Append(e.Data);
        _process.ErrorDataReceived += (_, e) => Append(e.Data);
        _process.Start();
        _process.BeginOutputReadLine();
        _process.BeginErrorReadLine();
    }

    /// <summary>The shipped teleoperation graph.</summary>
    public static string Graph => RepoFile("graphs", "teleop-lb.json");

    /// <summary>Everything printed so far (stdout and stderr).</summary>
    public string Output
    {
        get
        {
            lock (_output)
            {
                return _output.ToString();
            }
        }
    }

    public static string RepoFile(params string[] parts)
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var path = Path.Combine([dir.FullName, .. parts]);
            if (File.Exists(path))
            {
                return path;
            }
        }

        throw new FileNotFoundException($"{Path.Combine(parts)} not found above {AppContext.BaseDirectory}");
    }

    /// <summary>Waits until the output contains <paramref name="text"/>; returns the output.</summary>
    public string WaitFor(string text, TimeSpan timeout)
    {
        var waited = Stopwatch.StartNew();
        while (!Output.Contains(text, StringComparison.Ordinal))
        {
            Assert.True(waited.Elapsed < timeout && !_process.HasExited, $"no '{text}' after {waited.Elapsed.TotalSeconds:F0} s; output:\n{Output}");
            Thread.Sleep(50);
        }

        return Output;
    }

    /// <summary>Writes <paramref name="line"/> to the process's standard input (an operator typing it).</summary>
    public void Type(string line)
    {
        _process.StandardInput.WriteLine(line);
        _process.StandardInput.Flush();
    }

    /// <summary>Sends a signal (e.g. INT, TERM) to the process.</summary>
    public void Signal(string name)
    {
        using var kill = Process.Start("kill", ["-" + name, _process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)])!;
        kill.WaitForExit();
        Assert.True(kill.ExitCode == 0, $"kill -{name} failed (exited already?); output:\n{Output}");
    }

    /// <summary>Waits for the exit; returns the exit code.</summary>
    public int WaitForExit(TimeSpan timeout)
    {
        Assert.True(_process.WaitForExit(timeout), $"still running after {timeout.TotalSeconds:F0} s; output:\n{Output}");
        _process.WaitForExit(); // flush the output events
        return _process.ExitCode;
    }

    public void Dispose()
    {
        if (!_process.HasExited)
        {
            _process.Kill();
            _process.WaitForExit();
        }

        _process.Dispose();
    }

    private void Append(string? line)
    {
        if (line is null)
        {
            return;
        }

        lock (_output)
        {
            _output.AppendLine(line);
        }
    }
}
