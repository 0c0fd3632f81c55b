using System.Diagnostics;
using RobotControl.Kinematics.Inverse;
using RobotControl.Host.Session;

namespace RobotControl.Bench.Ik;

/// <summary>
/// Runs <see cref="IkSolver"/> over a target set, timing each solve, and counts bytes allocated. With repeat &gt; 1 every
/// target is timed that many times and its fastest time kept: on a shared, oversubscribed machine this drops the time a
/// solve sat descheduled (the role of BenchmarkDotNet's outlier removal); the thread-CPU mean is reported beside it.
/// </summary>
internal static class OurSolverRun
{

    public static OurRandomRun Random(IkTargetSet set, SolveCheck check, IkOptions options, int repeat)
    {
        var chain = set.Chain;
        var solver = new IkSolver(chain, options);
        var n = chain.JointCount;
        var seed = new double[n];
        chain.MidRange(seed);
        var q = new double[n];
        var count = set.Targets.Length;
        var times = new double[count];
        var solved = new bool[count];
        var iterations = new int[count];
        var status = new IkStatus[count];
        Warm(solver, set, seed, q);
        var before = GC.GetAllocatedBytesForCurrentThread();
        Array.Fill(times, double.PositiveInfinity);
        for (var pass = 0; pass < repeat; pass++)
        {
            for (var s = 0; s < count; s++)
            {
                var start = Stopwatch.GetTimestamp();
                var result = solver.Solve(set.Targets[s], seed, q);
                times[s] = Math.Min(times[s], Stopwatch.GetElapsedTime(start).TotalMicroseconds);
                iterations[s] = result.Iterations;
                status[s] = result.Status;
                solved[s] = check.Solved(set.Targets[s], q);
            }
        }

        var bytes = (GC.GetAllocatedBytesForCurrentThread() - before) / repeat;

        // Thread CPU time, target by target, in passes of their own (two clock reads per solve), the least of the
        // repeated passes as for wall time: interrupts and a sibling hyperthread's load also land on CPU time.
        var cpu = new double[count];
        Array.Fill(cpu, double.PositiveInfinity);
        for (var pass = 0; pass < repeat; pass++)
        {
            for (var s = 0; s < count; s++)
            {
                var cpuStart = ThreadCpuClock.NowNs();
                solver.Solve(set.Targets[s], seed, q);
                cpu[s] = Math.Min(cpu[s], (ThreadCpuClock.NowNs() - cpuStart) * 1e-3);
            }
        }

        var cpuTotal = cpu.Sum();
        var solvedCount = solved.Count(x => x);
        var stats = SolverStats.From($"ours (CCD + bounded LM, restarts), {set.Name}", times, solvedCount, IterationNote(iterations))
            with { MeanCpuUs = ThreadCpuClock.Available ? cpuTotal / count : double.NaN };
        return new OurRandomRun(set, stats, (double)bytes / count, times, cpu, iterations, solved, status);
    }

    public static (SolverStats Stats, double BytesPerSolve) Tracking(IkTargetSet trajectory, SolveCheck check, IkOptions options, int repeat)
    {
        var chain = trajectory.Chain;
        var solver = new IkSolver(chain, options);
        var n = chain.JointCount;
        var q = (double[])trajectory.Joints[0].Clone();
        var times = new double[trajectory.Targets.Length];
        var solved = 0;
        var verify = new double[n];
        Warm(solver, trajectory, q, new double[n]);
        var iterations = new int[trajectory.Targets.Length];
        var before = GC.GetAllocatedBytesForCurrentThread();
        Array.Fill(times, double.PositiveInfinity);
        for (var pass = 0; pass < repeat; pass++)
        {
            solved = 0;
            trajectory.Joints[0].CopyTo(q, 0);
            for (var s = 0; s < trajectory.Targets.Length; s++)
            {
                var start = Stopwatch.GetTimestamp();
                var result = solver.Solve(trajectory.Targets[s], q, q);
                times[s] = Math.Min(times[s], Stopwatch.GetElapsedTime(start).TotalMicroseconds);
                iterations[s] = result.Iterations;
                q.CopyTo(verify, 0);
                solved += check.Solved(trajectory.Targets[s], verify) ? 1 : 0;
            }
        }

        var bytes = (GC.GetAllocatedBytesForCurrentThread() - before) / repeat;
        trajectory.Joints[0].CopyTo(q, 0);
        var cpuStart = ThreadCpuClock.NowUs();
        foreach (var target in trajectory.Targets)
        {
            solver.Solve(target, q, q);
        }

        var cpu = (ThreadCpuClock.NowUs() - cpuStart) / trajectory.Targets.Length;
        var stats = SolverStats.From("ours, tracking", times, solved, IterationNote(iterations)) with { MeanCpuUs = cpu };
        return (stats, (double)bytes / trajectory.Targets.Length);
    }

    private static string IterationNote(int[] iterations)
    {
        var sorted = iterations.Order().ToArray();
        return string.Create(System.Globalization.CultureInfo.InvariantCulture,
            $"iterations mean {sorted.Average():F1}, median {sorted[sorted.Length / 2]}, p99 {sorted[(int)(0.99 * (sorted.Length - 1))]}, max {sorted[^1]}");
    }

    /// <summary>
    /// Solves for a second, then pauses, so tiered JIT has promoted the hot path (and the forward kinematics it calls)
    /// to optimised code before anything is timed.
    /// </summary>
    private static void Warm(IkSolver solver, IkTargetSet set, double[] seed, double[] q)
    {
        var start = Stopwatch.GetTimestamp();
        for (var s = 0; Stopwatch.GetElapsedTime(start).TotalSeconds < 1.0; s++)
        {
            solver.Solve(set.Targets[s % set.Targets.Length], seed, q);
        }

        Thread.Sleep(300);
    }
}
