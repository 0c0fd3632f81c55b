using System.Diagnostics;
using System.Globalization;
using System.Text.Json;
using RobotControl.Bench.Realtime;

namespace RobotControl.Bench.EStop;

/// <summary>
/// <c>estop [--graph graphs/teleop-lb.json] [--stops 200] [--scenarios idle,queued,flood] [--safe-state torque_off]
/// [--settle-ms 500] [--queued 50] [--flood-rate 2000] [--flood-clients 4] [--out file.json]</c>: E-STOP latency on the console's virtual
/// session (paced to the wall clock), from the arrival of <c>POST /api/estop</c> at the console server (its outermost
/// middleware) to the first hold or torque-off frame the host writes to the bus (<see cref="EStopTapLink"/>), p50 / p99 /
/// max per scenario: <c>idle</c>; <c>queued</c> (parameter reloads queued just before each stop); <c>flood</c> (API
/// reads at a target rate during the stops). Each stop comes <c>--settle-ms</c> after the robot is back at PEDAL_UP
/// (the virtual session sleeps off the virtual time that homing ran ahead of the wall clock in one piece: a stop
/// during that sleep waits for it; <c>--settle-ms 0</c> measures that case). The target: p99 within one bus cycle (median, same run) + 5 ms; PASS or
/// FAIL is printed, the exit code is 0 either way (1: a scenario could not run, 2: bad options).
/// </summary>
internal sealed class EStopBenchCommand : IBenchCommand
{
    private const double TargetMarginMs = 5;
    private static readonly JsonSerializerOptions JsonOptions = new() { WriteIndented = true, PropertyNamingPolicy = JsonNamingPolicy.SnakeCaseLower };
    private static readonly string[] Options = ["--graph", "--stops", "--scenarios", "--safe-state", "--settle-ms", "--queued", "--flood-rate", "--flood-clients", "--out"];
    private static readonly string[] Scenarios = ["idle", "queued", "flood"];

    public string Name => "estop";

    public string Description => "E-STOP latency: HTTP request arrival at the console to the first hold/torque-off frame on the wire (idle, queued, flood).";

    public int Run(string[] args)
    {
        var unknown = args.Where((a, i) => i % 2 == 0).FirstOrDefault(a => !Options.Contains(a));
        if (unknown is not null || args.Length % 2 != 0)
        {
            Console.Error.WriteLine($"estop: {(unknown is null ? $"{args[^1]} needs a value" : $"unknown option '{unknown}'")}; options: {string.Join(' ', Options)} (each with a value)");
            return 2;
        }

        var graph = BenchArgs.Value(args, "--graph") ?? "graphs/teleop-lb.json";
        var scenarios = (BenchArgs.Value(args, "--scenarios") ?? string.Join(',', Scenarios)).Split(',', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
        var safeState = BenchArgs.Value(args, "--safe-state") ?? "torque_off";
        string?[] integers =
        [
            Integer(args, "--stops", 200, 1, 100_000, out var stops),
            Integer(args, "--settle-ms", 500, 0, 60_000, out var settleMs),
            Integer(args, "--queued", 50, 1, 10_000, out var queued),
            Integer(args, "--flood-rate", 2000, 1, 100_000, out var floodRate),
            Integer(args, "--flood-clients", 4, 1, 256, out var floodClients),
        ];
        var problem = integers.FirstOrDefault(p => p is not null)
            ?? (scenarios.Length == 0 || scenarios.Any(s => !Scenarios.Contains(s)) ? $"--scenarios: give some of {string.Join(',', Scenarios)}" : null)
            ?? (safeState is not ("torque_off" or "hold") ? "--safe-state: give torque_off or hold" : null)
            ?? (!File.Exists(graph) ? $"--graph: no file {graph}" : null);
        if (problem is not null)
        {
            Console.Error.WriteLine($"estop: {problem}");
            return 2;
        }

        var settings = new EStopSettings(stops, settleMs, queued, floodRate, floodClients);
        var outFile = BenchArgs.Value(args, "--out");
        var command = $"dotnet run -c Release --project bench/RobotControl.Bench -- estop --graph {graph} --stops {stops} --scenarios {string.Join(',', scenarios)} --safe-state {safeState} --settle-ms {settleMs} --queued {queued} --flood-rate {floodRate} --flood-clients {floodClients}" + (outFile is null ? string.Empty : $" --out {outFile}");
        Console.WriteLine(command);
        var (results, failures) = RunAll(graph, safeState, scenarios, settings).GetAwaiter().GetResult();
        if (outFile is not null)
        {
            File.WriteAllText(outFile, JsonSerializer.Serialize(new { command, measuredUtc = DateTime.UtcNow, processors = Environment.ProcessorCount, safeState, settings, scenarios = results, failures }, JsonOptions));
            Console.WriteLine($"wrote {outFile}");
        }

        return failures.Count == 0 ? 0 : 1;
    }

    private static async Task<(List<EStopResult> Results, List<string> Failures)> RunAll(string graph, string safeState, string[] scenarios, EStopSettings settings)
    {
        var results = new List<EStopResult>();
        var failures = new List<string>();
        using var files = EStopRobotFiles.Write(graph, safeState);
        await using var run = await EStopRun.Start(files.Graph, safeState == "hold" ? StopFrame.Hold : StopFrame.TorqueOff).ConfigureAwait(false);
        Console.WriteLine($"console on {run.BaseUrl}, virtual robot, operator safe state {safeState}");
        foreach (var name in scenarios)
        {
            try
            {
                var result = await RunScenario(run, name, settings).ConfigureAwait(false);
                results.Add(result);
                Console.WriteLine(result.Line());
            }
            catch (Exception ex) when (ex is InvalidOperationException or HttpRequestException or TimeoutException)
            {
                Console.WriteLine($"{name}: did not run: {ex.Message}");
                failures.Add($"{name}: {ex.Message}");
            }
        }

        return (results, failures);
    }

    private static async Task<EStopResult> RunScenario(EStopRun run, string name, EStopSettings settings)
    {
        var loadStart = RealtimeBenchCommand.LoadAverage();
        var since = Stopwatch.GetTimestamp();
        var flood = name == "flood" ? FloodLoad.Start(run.BaseUrl, run.Token, settings.FloodRate, settings.FloodClients) : null;
        var samples = new StopSample[settings.Stops];
        var pendingAtStop = 0L;
        double floodRate = 0;
        long floodFailed = 0;
        try
        {
            Func<Task<Task>>? before = name == "queued" ? async () =>
            {
                var work = run.QueueReloads(settings.Queued);
                await Task.Delay(QueueSettle).ConfigureAwait(false); // the first reload is running when the stop comes
                pendingAtStop += work.Count(t => !t.IsCompleted);
                return Task.WhenAll(work);
            } : null;
            for (var i = 0; i < samples.Length; i++)
            {
                samples[i] = await run.Stop(TimeSpan.FromMilliseconds(settings.SettleMs), before).ConfigureAwait(false);
            }
        }
        finally
        {
            if (flood is not null)
            {
                floodRate = flood.AnsweredPerSecond;
                floodFailed = flood.Failed;
                await flood.DisposeAsync().ConfigureAwait(false);
            }
        }

        var latencies = Sorted(samples.Select(x => x.LatencyMs));
        var silent = Sorted(samples.Select(x => x.BusSilentAtArrivalMs));
        var periods = run.CyclePeriodsMs(since);
        Array.Sort(periods);
        var cycle = periods.Length == 0 ? double.NaN : RealtimeBenchCommand.Quantile(periods, 0.5);
        var p99 = RealtimeBenchCommand.Quantile(latencies, 0.99);
        return new EStopResult(
            name,
            latencies.Length,
            RealtimeBenchCommand.Quantile(latencies, 0.5),
            p99,
            latencies[^1],
            latencies[0],
            cycle,
            cycle + TargetMarginMs,
            p99 <= cycle + TargetMarginMs,
            samples.Count(x => !x.Confirmed),
            RealtimeBenchCommand.Quantile(silent, 0.99),
            silent[^1],
            name == "queued" ? pendingAtStop / (double)latencies.Length : null,
            name == "flood" ? floodRate : null,
            name == "flood" ? floodFailed : null,
            loadStart,
            RealtimeBenchCommand.LoadAverage());
    }

    private static double[] Sorted(IEnumerable<double> values)
    {
        var array = values.ToArray();
        Array.Sort(array);
        return array;
    }

    /// <summary>How long after queueing the reloads the stop is sent: long enough for the first to be running.</summary>
    private static readonly TimeSpan QueueSettle = TimeSpan.FromMilliseconds(10);

    /// <summary>Reads an integer option in [<paramref name="min"/>, <paramref name="max"/>]; returns the problem, or null.</summary>
    private static string? Integer(string[] args, string option, int fallback, int min, int max, out int value)
    {
        var text = BenchArgs.Value(args, option);
        value = fallback;
        return text is null || (int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out value) && value >= min && value <= max)
            ? null
            : $"{option}: give an integer {min}..{max}, not '{text}'";
    }
}

/// <summary>The stops' count, the wait before each, the queued scenario's reloads per stop, the flood's rate and clients.</summary>
internal sealed record EStopSettings(int Stops, int SettleMs, int Queued, int FloodRate, int FloodClients);

/// <summary>What one scenario measured (milliseconds).</summary>
internal sealed record EStopResult(
    string Scenario,
    int Stops,
    double P50Ms,
    double P99Ms,
    double MaxMs,
    double MinMs,
    double BusCycleMedianMs,
    double TargetP99Ms,
    bool Pass,
    int NotConfirmedWithin1S,
    double BusSilentAtArrivalP99Ms,
    double BusSilentAtArrivalMaxMs,
    double? QueuedPendingAtStop,
    double? FloodAnsweredPerSecond,
    long? FloodFailed,
    string LoadAverageAtStart,
    string LoadAverageAtEnd)
{
    /// <summary>One line for the console.</summary>
    public string Line() => string.Create(CultureInfo.InvariantCulture,
        $"{Scenario}: {Stops} stops, latency p50 {P50Ms:F2} ms, p99 {P99Ms:F2} ms, max {MaxMs:F2} ms (min {MinMs:F2}); bus cycle median {BusCycleMedianMs:F2} ms; target p99 <= {TargetP99Ms:F2} ms: {(Pass ? "PASS" : "FAIL")}; bus silent at arrival p99 {BusSilentAtArrivalP99Ms:F2} ms, max {BusSilentAtArrivalMaxMs:F2} ms; E_STOP not confirmed within 1 s: {NotConfirmedWithin1S}{(QueuedPendingAtStop is { } pending ? $"; reloads still queued or running at the stop {pending:F1} (mean)" : string.Empty)}{(FloodAnsweredPerSecond is { } rate ? $"; flood {rate:F0} answered/s, {FloodFailed} failed" : string.Empty)}; load {LoadAverageAtStart} -> {LoadAverageAtEnd}");
}
