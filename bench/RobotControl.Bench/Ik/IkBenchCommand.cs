using System.Globalization;
using System.Text.Json;
using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// <c>ik --robot FILE [--samples N] [--seed S] [--json OUT] [--baseline-samples M] [--tracking-steps T] [--axes all|z|none]
/// [--no-kdl] [--no-baseline] [--repeat K] [--sets random,near_singular,at_limits,near_boundary] [--special-samples M] [--worst W]</c>:
/// the same random reachable targets to our solver, the reference-design baseline and Orocos KDL; then our solver alone on
/// the hard sets (<see cref="IkSpecialSets"/>), with each set's maximum, p99.9, slowest targets and every failure in
/// the JSON. <c>ik --replay OUT.json</c> solves those again (<see cref="IkReplay"/>).
/// </summary>
internal sealed class IkBenchCommand : IBenchCommand
{
    private const string Usage = "usage: ik --robot FILE [--samples N] [--seed S] [--json OUT] [--baseline-samples M] [--tracking-steps T] [--axes all|z|none] [--no-kdl] [--no-baseline] [--repeat K] [--sets random,near_singular,at_limits,near_boundary] [--special-samples M] [--worst W] | ik --replay OUT.json [--repeat K]";

    private static readonly JsonSerializerOptions JsonOptions = new()
    {
        WriteIndented = true,
        NumberHandling = System.Text.Json.Serialization.JsonNumberHandling.AllowNamedFloatingPointLiterals,
    };

    public string Name => "ik";

    public string Description => "inverse kinematics: ours vs the reference-design baseline vs Orocos KDL (JSON)";

    public int Run(string[] args)
    {
        IkBenchOptions? options;
        try
        {
            options = IkBenchOptions.Parse(args);
        }
        catch (Exception e) when (e is ArgumentException or FormatException or OverflowException)
        {
            Console.Error.WriteLine($"ik: {e.Message}");
            options = null;
        }

        if (options is null)
        {
            Console.Error.WriteLine(Usage);
            return 2;
        }

        if (options.Replay is not null)
        {
            return IkReplay.Run(options.Replay, options.Repeat, JsonOptions);
        }

        RobotDefinition robot;
        try
        {
            robot = RobotLoader.Load(options.Robot);
        }
        catch (RobotDataException e)
        {
            Console.Error.WriteLine(e.Message);
            return 2;
        }

        var chain = new KinematicChain(robot);
        var axes = options.Axes ?? (chain.JointCount >= 5 ? OrientationAxes.All : OrientationAxes.Z);
        var ikOptions = new IkOptions();
        var check = new SolveCheck(chain, ikOptions.PositionToleranceMm, ikOptions.OrientationToleranceRad);
        var targets = IkTargetSet.Random(chain, options.Samples, options.Seed, axes);
        Console.Error.WriteLine($"{robot.Name}: {options.Samples} targets (axes {axes}), seed {options.Seed}");

        var loadBefore = LoadAverage();
        var solvers = new List<SolverStats>();
        var (evaluateUs, normalUs, rankUs) = IkCostProfile.Measure(targets, ikOptions);
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"parts of a solve (median): forward kinematics {evaluateUs:F3} us, normal equations {normalUs:F3} us, ranking the {RestartSeeds.Count} restart seeds {rankUs:F2} us"));
        var sets = new List<IkSetReport>();
        var random = OurSolverRun.Random(targets, check, ikOptions, options.Repeat);
        var (ours, bytesPerSolve) = (random.Stats, random.BytesPerSolve);
        solvers.Add(ours);
        Print(ours);
        if (options.Sets.Contains("random"))
        {
            sets.Add(IkSetReport.From(random, options.Worst));
            PrintTail(sets[^1]);
        }

        foreach (var name in IkBenchOptions.SpecialSetNames.Where(options.Sets.Contains))
        {
            var set = name switch
            {
                "near_singular" => IkSpecialSets.NearSingular(chain, options.SpecialSamples, options.Seed, axes),
                "at_limits" => IkSpecialSets.AtLimits(chain, options.SpecialSamples, options.Seed, axes),
                _ => IkSpecialSets.NearBoundary(chain, options.SpecialSamples, options.Seed, axes),
            };
            var run = OurSolverRun.Random(set, check, ikOptions, options.Repeat);
            Print(run.Stats);
            sets.Add(IkSetReport.From(run, options.Worst));
            PrintTail(sets[^1]);
        }

        var trajectory = IkTargetSet.Trajectory(chain, options.TrackingSteps, options.Seed, axes, 1.0);
        var (tracking, trackingBytes) = OurSolverRun.Tracking(trajectory, check, ikOptions, options.Repeat);
        Print(tracking);

        if (options.BaselineSamples > 0)
        {
            var baseline = ReferenceIkRun.Random(targets, Math.Min(options.BaselineSamples, options.Samples), check);
            solvers.Add(baseline);
            Print(baseline);
        }

        var kdlNote = "skipped (--no-kdl)";
        if (options.Kdl)
        {
            var kdl = KdlRunner.Run(targets, check, options.Repeat, out kdlNote);
            foreach (var stats in kdl)
            {
                solvers.Add(stats);
                Print(stats);
            }

            if (kdl.Count == 0)
            {
                Console.Error.WriteLine($"KDL: {kdlNote}");
            }
        }

        if (options.Json is not null)
        {
            var document = new
            {
                robot = robot.Name,
                robot_file = options.Robot,
                samples = options.Samples,
                seed = options.Seed,
                timing = $"wall time per solve (Stopwatch), fastest of {options.Repeat} passes per target for ours and KDL, 1 pass for the baseline; ours' cpu: thread CPU time (CLOCK_THREAD_CPUTIME_ID) per solve in passes of their own, least of {options.Repeat} per target (it includes two clock reads); KDL's mean_cpu_us: thread CPU time of one untimed pass / samples",
                axes = axes.ToString(),
                tolerance = new { position_mm = ikOptions.PositionToleranceMm, orientation_rad = ikOptions.OrientationToleranceRad },
                solvers = solvers.Select(s => new
                {
                    name = s.Name,
                    samples = s.Samples,
                    solve_rate = s.SolveRate,
                    mean_us = s.MeanUs,
                    median_us = s.MedianUs,
                    p99_us = s.P99Us,
                    p99_9_us = s.P999Us,
                    max_us = s.MaxUs,
                    mean_cpu_us = double.IsFinite(s.MeanCpuUs) ? s.MeanCpuUs : (double?)null,
                    note = s.Note,
                }),
                tracking = new
                {
                    steps = trajectory.Targets.Length,
                    solve_rate = tracking.SolveRate,
                    mean_us = tracking.MeanUs,
                    median_us = tracking.MedianUs,
                    p99_us = tracking.P99Us,
                    p99_9_us = tracking.P999Us,
                    max_us = tracking.MaxUs,
                    mean_cpu_us = tracking.MeanCpuUs,
                    note = tracking.Note,
                },
                allocation = new
                {
                    bytes_per_solve = bytesPerSolve,
                    tracking_bytes_per_solve = trackingBytes,
                    method = "GC.GetAllocatedBytesForCurrentThread around the timed loop; BenchmarkDotNet [MemoryDiagnoser]: run `-- ik-alloc`",
                },
                sets,
                parts_us = new { forward_kinematics = evaluateUs, normal_equations = normalUs, rank_restart_seeds = rankUs, method = "median of 200 batches of 1,000 calls (ranking: 100), Stopwatch" },
                kdl = kdlNote,
                host = new { processors = Environment.ProcessorCount, load_average_before = loadBefore, load_average_after = LoadAverage() },
            };
            File.WriteAllText(options.Json, JsonSerializer.Serialize(document, JsonOptions));
            Console.Error.WriteLine($"wrote {options.Json}");
        }

        return 0;
    }

    /// <summary>1-minute load average (Linux), so a reader can tell a busy machine's numbers from a quiet one's.</summary>
    private static double? LoadAverage()
    {
        try
        {
            var text = File.ReadAllText("/proc/loadavg");
            return double.Parse(text.Split(' ')[0], CultureInfo.InvariantCulture);
        }
        catch (IOException)
        {
            return null;
        }
        catch (UnauthorizedAccessException)
        {
            return null;
        }
    }

    private static void PrintTail(IkSetReport r) =>
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"  {r.Set}: {r.Solved}/{r.Samples} solved; wall p99.9 {r.Wall.P999:F2} us, max {r.Wall.Max:F2} us; cpu p99.9 {r.Cpu.P999:F2} us, max {r.Cpu.Max:F2} us; iterations max {r.Iterations.Max}; failures {r.Failures.Count}"));

    private static void Print(SolverStats s) =>
        Console.WriteLine(string.Create(CultureInfo.InvariantCulture,
            $"{s.Name,-44} n={s.Samples,6} rate={100 * s.SolveRate,8:F3} %  mean={s.MeanUs,10:F2} us  median={s.MedianUs,10:F2} us  p99={s.P99Us,10:F2} us  cpu mean={s.MeanCpuUs,9:F2} us {s.Note}"));
}
