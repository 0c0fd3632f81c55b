using RobotControl.Definitions.Loading;
using RobotControl.Definitions.Model;
using RobotControl.Kinematics.Forward;
using RobotControl.TestSupport;

namespace RobotControl.Kinematics.Tests;

/// <summary>The shipped robot files (loaded once, by <see cref="ShippedRobots"/>) and random joint draws.</summary>
internal static class TestRobots
{
    public static RobotDefinition Crb => ShippedRobots.Crb;

    public static RobotDefinition Lb => ShippedRobots.Lb;

    public static TheoryData<string> Names => new() { "crb-1.0.json", "lb-1.0.json" };

    public static RobotDefinition ByFile(string file) => file switch
    {
        "crb-1.0.json" => Crb,
        "lb-1.0.json" => Lb,
        _ => RobotLoader.Load(PathOf(file)),
    };

    /// <summary>Fills <paramref name="q"/> with joint values uniform within the chain's limits (deterministic for a seeded Random).</summary>
    public static void FillRandomJoints(KinematicChain chain, Random random, Span<double> q)
    {
        for (var i = 0; i < q.Length; i++)
        {
            q[i] = chain.MinRad[i] + (random.NextDouble() * (chain.MaxRad[i] - chain.MinRad[i]));
        }
    }

    public static string PathOf(string file) => RepositoryPaths.Robot(file);
}
