using System.Diagnostics;
using RobotControl.Kinematics.Forward;
using RobotControl.Kinematics.Inverse;

namespace RobotControl.Bench.Ik;

/// <summary>
/// What the parts of a solve cost on this machine (median of many timed batches): one forward-kinematics evaluation,
/// one Levenberg-Marquardt iteration's normal equations, and ranking the fixed restart seeds against a target. With
/// the iteration ceiling they give the time bound a solve can be budgeted for.
/// </summary>
internal static class IkCostProfile
{
    private const int Batch = 1_000;
    private const int Batches = 200;

    public static (double EvaluateUs, double NormalEquationsUs, double RankUs) Measure(IkTargetSet set, IkOptions options)
    {
        var chain = set.Chain;
        var problem = new IkProblem(chain, options);
        var seeds = new RestartSeeds(chain, chain.MinRad, chain.MaxRad);
        var n = chain.JointCount;
        var jacobian = new double[12 * n];
        var normal = new double[n * n];
        var jtr = new double[n];
        problem.SetTarget(set.Targets[0]);
        var joints = set.Joints;
        var evaluate = Median(() =>
        {
            for (var k = 0; k < Batch; k++)
            {
                problem.Evaluate(joints[k % joints.Length]);
            }
        });
        var normalEquations = Median(() =>
        {
            for (var k = 0; k < Batch; k++)
            {
                problem.NormalEquations(jacobian, normal, jtr);
            }
        });
        var rank = Median(() =>
        {
            for (var k = 0; k < Batch / 10; k++)
            {
                seeds.Rank(problem);
            }
        }) * 10;
        return (evaluate, normalEquations, rank);
    }

    private static double Median(Action batch)
    {
        batch();
        var times = new double[Batches];
        for (var b = 0; b < Batches; b++)
        {
            var start = Stopwatch.GetTimestamp();
            batch();
            times[b] = Stopwatch.GetElapsedTime(start).TotalMicroseconds / Batch;
        }

        Array.Sort(times);
        return times[Batches / 2];
    }
}
