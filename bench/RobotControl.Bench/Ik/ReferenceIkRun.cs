using System.Diagnostics;
using RobotControl.Kinematics.Inverse;
using RobotControl.Host.Session;

namespace RobotControl.Bench.Ik;

/// <summary>Runs the baseline over the first <c>count</c> targets of a set.</summary>
internal static class ReferenceIkRun
{
    public static SolverStats Random(IkTargetSet set, int count, SolveCheck check)
    {
        var chain = set.Chain;
        var solver = new ReferenceIkSolver(chain, new IkOptions());
        var n = chain.JointCount;
        var seed = new double[n];
        chain.MidRange(seed);
        var q = new double[n];
        var times = new double[count];
        var solved = 0;
        var warm = Stopwatch.GetTimestamp();
        for (var s = 0; Stopwatch.GetElapsedTime(warm).TotalSeconds < 1.0; s++)
        {
            solver.Solve(set.Targets[s % count], seed, q);
        }

        Thread.Sleep(300);

        for (var s = 0; s < count; s++)
        {
            var start = Stopwatch.GetTimestamp();
            solver.Solve(set.Targets[s], seed, q);
            times[s] = Stopwatch.GetElapsedTime(start).TotalMicroseconds;
            solved += check.Solved(set.Targets[s], q) ? 1 : 0;
        }

        var note = count < set.Targets.Length ? $"first {count} of the {set.Targets.Length} targets" : string.Empty;
        var cpuStart = ThreadCpuClock.NowUs();
        for (var s = 0; s < count; s++)
        {
            solver.Solve(set.Targets[s], seed, q);
        }

        var cpu = (ThreadCpuClock.NowUs() - cpuStart) / count;
        return SolverStats.From("baseline (reference CCD 15k + L-BFGS, clamp)", times, solved, note) with { MeanCpuUs = cpu };
    }
}
