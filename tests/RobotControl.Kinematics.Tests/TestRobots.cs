using RobotControl.Hardware.Loading;
using RobotControl.Hardware.Model;
using RobotControl.Kinematics.Forward;

namespace RobotControl.Kinematics.Tests;

/// <summary>The shipped robot files, loaded once.</summary>
internal static class TestRobots
{
    private static readonly Lazy<RobotDefinition> CrbLazy = new(() => RobotLoader.Load(PathOf("crb-1.0.json")));
    private static readonly Lazy<RobotDefinition> LbLazy = new(() => RobotLoader.Load(PathOf("lb-1.0.json")));

    public static RobotDefinition Crb => CrbLazy.Value;

    public static RobotDefinition Lb => LbLazy.Value;

    public static TheoryData<string> Names => new() { "crb-1.0.json", "lb-1.0.json" };

    public static RobotDefinition ByFile(string file) => file switch
    {
        "crb-1.0.json" => Crb,
        "lb-1.0.json" => Lb,
        _ => RobotLoader.Load(PathOf(file)),
    };

    public static string RobotsDirectory { get; } = FindRobotsDirectory();

    /// <summary>Fills <paramref name="q"/> with joint values uniform within the chain's limits (deterministic for a seeded Random).</summary>
    public static void FillRandomJoints(KinematicChain chain, Random random, Span<double> q)
    {
        for (var i = 0; i < q.Length; i++)
        {
            q[i] = chain.MinRad[i] + (random.NextDouble() * (chain.MaxRad[i] - chain.MinRad[i]));
        }
    }

    public static string PathOf(string file) => Path.Combine(RobotsDirectory, file);

    private static string FindRobotsDirectory()
    {
        for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir is not null; dir = dir.Parent)
        {
            var candidate = Path.Combine(dir.FullName, "hardware", "robots");
            if (File.Exists(Path.Combine(candidate, "crb-1.0.json")))
            {
                return candidate;
            }
        }

        throw new InvalidOperationException("hardware/robots not found above " + AppContext.BaseDirectory);
    }
}
