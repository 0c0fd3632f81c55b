using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.Bench.Realtime;
using RobotControl.Bus.Client;
using RobotControl.Bus.Protocol;
using RobotControl.Bus.Transports;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Modules;

namespace RobotControl.Bench.Stall;

/// <summary>
/// <c>stall [--graph graphs/teleop-lb.json] [--stalls-ms 20,50,100,200,400,1000] [--repeat 3] [--out file.json]</c>: the
/// host stalls for real on the pty path. For each length and repetition, a fresh virtual robot behind its pty
/// (<c>robotctl bus-sim --pty</c>, the real firmware) and a wall-clock <c>robotctl run</c> on it; one second in, the run's
/// process is stopped with SIGSTOP for that long and continued with SIGCONT. Each case must end as graded: under the
/// stall limit nothing; up to the modules' torque-off stage (<c>modules.watchdog_off_ms</c>) a soft <c>host_stall</c>
/// trip and no E-STOP, the harness (as a surgeon) having pressed the pedal again; from that stage an E-STOP whose modules
/// switched their motors off themselves. After each run the modules are read back independently over the pty: torque
/// off everywhere, and <c>bus_watchdog</c> latched exactly in the E-STOP cases. PASS or FAIL per case and overall; exit
/// code 0 either way (1: a case could not run, 2: bad options).
/// </summary>
internal sealed class StallBenchCommand : IBenchCommand
{
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower };
    private static readonly string[] Options = ["--graph", "--stalls-ms", "--repeat", "--out"];

    public string Name => "stall";

    public string Description => "Host stalls on the pty path: SIGSTOP the run for each length; every case must end as graded (nothing / soft trip / E-STOP), read back.";

    public int Run(string[] args)
    {
        var unknown = args.Where((a, i) => i % 2 == 0).FirstOrDefault(a => !Options.Contains(a));
        if (unknown is not null || args.Length % 2 != 0)
        {
            Console.Error.WriteLine($"stall: {(unknown is null ? $"{args[^1]} needs a value" : $"unknown option '{unknown}'")}; options: {string.Join(' ', Options)} (each with a value)");
            return 2;
        }

        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var robotFile = "hardware/robots/lb-1.0.json";
        var stalls = (BenchArgs.Value(args, "--stalls-ms") ?? "20,50,100,200,400,1000").Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        var lengths = stalls.Select(s => int.TryParse(s, NumberStyles.None, CultureInfo.InvariantCulture, out var ms) && ms is > 0 and <= 60_000 ? ms : -1).ToArray();
        var repeat = int.TryParse(BenchArgs.Value(args, "--repeat") ?? "3", NumberStyles.None, CultureInfo.InvariantCulture, out var r) ? r : -1;
        var problem = lengths.Length == 0 || lengths.Any(l => l < 0) ? "--stalls-ms: give lengths from 1 to 60000 ms, comma-separated"
            : repeat is < 1 or > 100 ? "--repeat: give 1 to 100"
            : !File.Exists(graph) ? $"--graph: no file {graph}" : null;
        if (problem is not null)
        {
            Console.Error.WriteLine($"stall: {problem}");
            return 2;
        }

        var robot = RobotLoader.Load(robotFile);
        var limitMs = robot.Safety.DeadlineMissesInARow; // at 1 kHz: the stall limit in ms
        var stageMs = robot.Modules.WatchdogOffMs;
        Console.WriteLine($"stall: {graph}, stalls {string.Join(", ", lengths)} ms x {repeat}; stall limit {limitMs} ms, the modules hold from {robot.Modules.WatchdogMs} ms and switch off at {stageMs} ms");
        var cases = new List<StallCase>();
        foreach (var ms in lengths)
        {
            for (var i = 0; i < repeat; i++)
            {
                try
                {
                    var c = RunCase(graph, robotFile, robot, ms, Expected(ms, limitMs, stageMs));
                    cases.Add(c);
                    Console.WriteLine(c.Line());
                }
                catch (Exception ex) when (ex is IOException or InvalidOperationException or JsonException)
                {
                    Console.Error.WriteLine($"stall: the {ms} ms case could not run: {ex.Message}");
                    return 1;
                }
            }
        }

        var passed = cases.Count(c => c.Pass);
        Console.WriteLine($"stall: {passed} of {cases.Count} cases ended as graded: {(passed == cases.Count ? "PASS" : "FAIL")}");
        if (BenchArgs.Value(args, "--out") is { } outFile)
        {
            File.WriteAllText(outFile, JsonSerializer.Serialize(new { graph, limit_ms = limitMs, torque_off_stage_ms = stageMs, cases }, JsonOptions));
        }

        return 0;
    }

    /// <summary>What a stall of <paramref name="ms"/> must give: under the limit nothing, up to the torque-off stage a soft trip, from it an E-STOP.</summary>
    private static string Expected(int ms, int limitMs, int stageMs) => ms < limitMs ? "nothing" : ms < stageMs ? "soft" : "e_stop";

    private static StallCase RunCase(string graph, string robotFile, RobotDefinition robot, int ms, string expected)
    {
        var (sim, transport) = ChildProcess.StartBusSim(robotFile, 0, null);
        using (sim)
        {
            var report = Path.Combine(Path.GetTempPath(), $"rc-stall-{Guid.NewGuid():N}.json");
            var cli = Path.GetFullPath(Path.Combine("src", "RobotControl.Cli", "bin", "Release", "net10.0", "robotctl.dll"));
            var start = new ProcessStartInfo("dotnet") { RedirectStandardOutput = true, RedirectStandardError = true, RedirectStandardInput = true, UseShellExecute = false };
            foreach (var a in new[] { cli, "run", graph, "--transport", transport, "--duration", "3s", "--continue-on-fault", "--report", report })
            {
                start.ArgumentList.Add(a);
            }

            using var run = Process.Start(start) ?? throw new InvalidOperationException("robotctl run did not start");
            var err = run.StandardError.ReadToEndAsync();
            string? line;
            while ((line = run.StandardOutput.ReadLine()) is not null && !line.TrimStart().StartsWith("t=", StringComparison.Ordinal))
            {
            }

            var rest = run.StandardOutput.ReadToEndAsync();
            Thread.Sleep(1000);
            var stopped = Stopwatch.GetTimestamp();
            Signal(run.Id, "STOP");
            Thread.Sleep(ms);
            Signal(run.Id, "CONT");
            var heldMs = Stopwatch.GetElapsedTime(stopped).TotalMilliseconds;
            if (!run.WaitForExit(60_000))
            {
                run.Kill(entireProcessTree: true);
                throw new InvalidOperationException($"robotctl run did not end: {rest.Result}{err.Result}");
            }

            if (!File.Exists(report))
            {
                throw new InvalidOperationException($"robotctl run wrote no report (exit {run.ExitCode}): {err.Result.Trim()}");
            }

            using var doc = JsonDocument.Parse(File.ReadAllText(report));
            File.Delete(report);
            var safety = doc.RootElement.GetProperty("safety");
            var trips = safety.GetProperty("trips").EnumerateArray().ToList();
            var stall = trips.Where(t => t.GetProperty("check").GetString() == "host_stall").Select(t => (Ms: t.GetProperty("measured").GetDouble(), Soft: t.GetProperty("soft").GetBoolean())).ToList();
            var readBack = ReadBack(transport, robot);
            var outcome = trips.Any(t => !t.GetProperty("soft").GetBoolean()) ? "e_stop" : trips.Count > 0 ? "soft" : "nothing";
            var final = safety.GetProperty("final_run_level").GetString()!;
            var pass = outcome == expected
                && readBack.TorqueOffEverywhere
                && readBack.WatchdogLatched == (expected == "e_stop" ? readBack.Modules : 0)
                && (expected != "soft" || safety.GetProperty("re_engagements").GetInt32() >= 1);
            return new StallCase(
                ms,
                Math.Round(heldMs, 1),
                expected,
                outcome,
                stall.Count == 0 ? null : Math.Round(stall.Max(s => s.Ms), 1),
                final,
                safety.GetProperty("re_engagements").GetInt32(),
                [.. trips.Select(t => $"{t.GetProperty("check").GetString()} {t.GetProperty("joint").GetString()} {t.GetProperty("measured").GetDouble():G4} {t.GetProperty("unit").GetString()} at {t.GetProperty("time_s").GetDouble():F3} s{(t.GetProperty("soft").GetBoolean() ? " (soft)" : string.Empty)}".Replace("  ", " ", StringComparison.Ordinal))],
                readBack.TorqueOffEverywhere,
                readBack.WatchdogLatched,
                pass);
        }
    }

    private static void Signal(int pid, string signal)
    {
        using var kill = Process.Start("kill", [$"-{signal}", pid.ToString(CultureInfo.InvariantCulture)]);
        kill.WaitForExit();
    }

    /// <summary>Every module read back over the pty, by a client of its own: torque on any channel, and a latched bus watchdog.</summary>
    private static (int Modules, bool TorqueOffEverywhere, int WatchdogLatched) ReadBack(string transport, RobotDefinition robot)
    {
        var table = ControlTable.Firmware;
        var torque = table["torque_enable"];
        var status = table["hardware_error_status"];
        using var client = new BusClient(LinkFactory.Open(transport), TimeProvider.System, new BusClientOptions { ResponseMargin = TimeSpan.FromMilliseconds(50) });
        var channels = new byte[((torque.Count - 1) * torque.Stride) + torque.Size];
        var error = new byte[1];
        var off = true;
        var latched = 0;
        foreach (var m in robot.Modules.Modules)
        {
            off &= client.Read(m.Id, torque.At(0), channels, 3).Succeeded && channels.All(b => b == 0);
            if (client.Read(m.Id, status.At(0), error, 3).Succeeded && new HardwareErrors(error[0]).HasAny(HardwareErrors.BusWatchdog))
            {
                latched++;
            }
        }

        return (robot.Modules.Modules.Count, off, latched);
    }

    /// <summary>One case: the stall asked for and held, what it should give and what it gave, the read-back.</summary>
    private sealed record StallCase(int StallMs, double HeldMs, string Expected, string Outcome, double? HostStallMeasuredMs, string FinalRunLevel, int ReEngagements, IReadOnlyList<string> Trips, bool TorqueOffAtEnd, int WatchdogLatched, bool Pass)
    {
        public string Line() => string.Create(CultureInfo.InvariantCulture,
            $"  {StallMs,5} ms (held {HeldMs:F1}): expected {Expected,-7} got {Outcome,-7} host_stall {(HostStallMeasuredMs is { } m ? $"{m:F1} ms" : "-"),-9} final {FinalRunLevel,-10} re-engaged {ReEngagements}  read back: torque off {TorqueOffAtEnd}, bus_watchdog latched {WatchdogLatched}  {(Pass ? "ok" : "NOT AS GRADED")}  [{string.Join("; ", Trips)}]");
    }
}
